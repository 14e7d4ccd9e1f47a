#include "grading/live_cpp.h"

#include <algorithm>
#include <fstream>

#include "core/platform.h"
#include "core/untrusted.h"
#include "grading/cpp_exercise.h"
#include "grading/live_gl.h"
#include "grading/platform_process.h"

namespace shadowlab {

LiveCppExercise::~LiveCppExercise() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
  std::error_code ec;
  if (!folder_.empty()) std::filesystem::remove_all(folder_, ec);
}

void LiveCppExercise::reset() {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return !building_; });  // a build under way finishes first
  built_text_.clear();
  tried_text_.clear();
  gl_built_text_.clear();
  gl_tried_text_.clear();
  ready_.reset();
  message_.clear();
  in_use_ = false;
}

void LiveCppExercise::poll(const Lab& lab, Impl impl, bool wait) {
  if (&lab != lab_ || impl != impl_) {
    reset();
    const std::lock_guard lock(mutex_);
    if (&lab != lab_) {
      last_.reset();
      gl_last_.reset();
      failed_text_.clear();
    }
    lab_ = &lab;
    impl_ = impl;
  }
  if (impl != Impl::Exercise || building_) return;
  if (!lab.gl_exercise_files.empty() && live_gl_exercise_supported(lab.gl_exercise_files.front())) {  // (no lab has both kinds yet; a CPU build's hooks would drop the GL code)
    poll_gl(lab, impl, wait);
    if (building_) return;
  }
  const std::vector<std::string>& files = lab.exercise_files;
  for (std::size_t slot = 0; slot < files.size(); ++slot) {
    const auto copy = lab.compiled_copies.find(files[slot]);
    if (copy == lab.compiled_copies.end()) continue;  // a shader: the renderer reloads it itself
    std::string text;
    try {
      text = without_carriage_returns(platform::read_regular_file(data_dir() / files[slot], kMaxExerciseSourceBytes));
    } catch (const std::exception& e) {
      const std::lock_guard lock(mutex_);
      message_ = files[slot] + ": " + e.what();
      return;
    }
    const std::string compiled = without_carriage_returns(std::string(copy->second));
    const std::string& current = built_text_.empty() ? compiled : built_text_;
    if (text == current || text == tried_text_ || text == failed_text_) continue;
    tried_text_ = text;
    if (reuse(last_, text, built_text_)) return;
    if (text == compiled) {  // edited back to the compiled copy: the program's own hooks again
      const std::lock_guard lock(mutex_);
      built_text_.clear();
      ready_ = lab.hooks(impl);
      message_.clear();
      in_use_ = false;
      return;
    }
    if (const std::string& why = platform::grading_unavailable(); !why.empty()) {
      const std::lock_guard lock(mutex_);
      message_ = files[slot] + " has changed: rebuild shadowlab (cmake --build build) to use it (" + why + ")";
      return;
    }
    start_build(lab, impl, slot, text);
    return;  // one file at a time
  }
}

bool LiveCppExercise::reuse(const std::optional<std::pair<std::string, Features>>& last, const std::string& text,
                             std::string& built_text) {
  if (!last || text != last->first) return false;
  const std::lock_guard lock(mutex_);
  built_text = text;
  ready_ = last->second;
  message_.clear();
  in_use_ = true;
  return true;
}

void LiveCppExercise::start_build(const Lab& lab, Impl impl, std::size_t slot, const std::string& text) {
  if (folder_.empty()) folder_ = platform::make_private_temp_dir("shadowlab-live-");
  // A new file per build: a built program is kept per file (grading/cpp_exercise.h, built_once).
  const std::filesystem::path dir = folder_ / std::to_string(++generation_);
  std::filesystem::create_directories(dir);
  const std::filesystem::path copy = dir / std::filesystem::path(lab.exercise_files[slot]).filename();
  std::ofstream(copy, std::ios::binary) << text;
  SlotFiles files = lab.files(impl);
  files.at(slot) = copy;
  building_ = true;
  run_on_worker([this, &lab, files, text] {
    std::optional<Features> hooks;
    std::string error;
    try {
      hooks = lab.hooks_for(files);
    } catch (const std::exception& e) {  // ExerciseError (compile_error...), or the grader's own failure
      error = e.what();
    }
    finish_build(std::move(hooks), error, text, false);
  });
}

void LiveCppExercise::poll_gl(const Lab& lab, Impl impl, bool wait) {
  const std::string& file = lab.gl_exercise_files.front();
  std::string text;
  try {
    text = without_carriage_returns(platform::read_regular_file(data_dir() / file, kMaxExerciseSourceBytes));
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    message_ = file + ": " + e.what();
    return;
  }
  if (text == gl_built_text_ || text == gl_tried_text_ || text == failed_text_) return;
  gl_tried_text_ = text;
  if (reuse(gl_last_, text, gl_built_text_)) return;
  if (const std::string& why = platform::grading_unavailable(); !why.empty()) {
    const std::lock_guard lock(mutex_);
    message_ = file + ": the window draws with the program's own (the solution's) functions: building yours "
                      "into it needs Linux here (" + why + "); `shadowlab check --lab " + std::to_string(lab.number) +
               "` grades your file";
    return;
  }
  // Asked to, the first build for this lab waits (0.4 s measured): the window's first frame then draws the
  // student's file, not the solution's for a moment; a build after a save runs in the background.
  start_gl_build(lab, impl, text, wait && gl_built_text_.empty());
}

void LiveCppExercise::start_gl_build(const Lab& lab, Impl impl, const std::string& text, bool wait) {
  if (folder_.empty()) folder_ = platform::make_private_temp_dir("shadowlab-live-");
  const std::filesystem::path dir = folder_ / std::to_string(++generation_);  // a new library per build
  building_ = true;
  auto job = [this, &lab, impl, dir, text] {
    std::optional<Features> hooks;
    std::string error;
    try {
      Features features = lab.hooks(impl);
      features.gl_host = build_live_gl_exercise(dir, lab.gl_exercise_files.front(), text, features.gl_host);
      hooks = std::move(features);
    } catch (const std::exception& e) {
      error = e.what();
    }
    finish_build(std::move(hooks), error, text, true);
  };
  if (wait) job();
  else run_on_worker(std::move(job));
}

void LiveCppExercise::run_on_worker(std::function<void()> job) {
  if (!worker_.joinable())
    worker_ = std::thread([this] {
      std::unique_lock lock(mutex_);
      for (;;) {
        wake_.wait(lock, [this] { return stopping_ || job_; });
        if (stopping_) return;
        std::function<void()> next = std::move(job_);
        job_ = nullptr;
        lock.unlock();
        next();
        lock.lock();
      }
    });
  {
    const std::lock_guard lock(mutex_);
    job_ = std::move(job);
  }
  wake_.notify_all();
}

void LiveCppExercise::finish_build(std::optional<Features> hooks, const std::string& error, const std::string& text,
                                   bool gl) {
  {
    const std::lock_guard lock(mutex_);
    if (hooks) {
      (gl ? gl_last_ : last_).emplace(text, *hooks);
      ready_ = std::move(hooks);
      (gl ? gl_built_text_ : built_text_) = text;
      message_.clear();
      in_use_ = true;
    } else {
      message_ = printable(error, 4000);
    }
    building_ = false;
  }
  wake_.notify_all();  // reset() may be waiting for this build
}

std::optional<Features> LiveCppExercise::take_hooks() {
  const std::lock_guard lock(mutex_);
  std::optional<Features> hooks = std::move(ready_);
  ready_.reset();
  return hooks;
}

void LiveCppExercise::failed(const std::string& why) {
  const std::lock_guard lock(mutex_);
  if (last_) failed_text_ = last_->first;
  last_.reset();
  built_text_.clear();
  in_use_ = false;
  message_ = printable(why, 4000);
}

bool LiveCppExercise::has_error() const {
  const std::lock_guard lock(mutex_);
  return !building_ && !message_.empty();
}

std::string LiveCppExercise::message() const {
  const std::lock_guard lock(mutex_);
  if (building_) return "building your edited C++ exercise...";
  if (!message_.empty()) return message_ + (in_use_ ? " (your last good build keeps running)" : " (the program's copy keeps running)");
  if (in_use_) return "your edited C++ exercise is live (built from the file on disk)";
  return {};
}

}  // namespace shadowlab
