// A lab's C++ exercise, live in the window: when the student saves exercise.cpp, the window's hooks are
// built again from the file on disk, on a worker thread, and used from the next frame; a build error is
// shown (file:line:col, the compiler's words) while the last good hooks keep running, as for shaders.
//
// The file is built the way Check builds an edited exercise (grading/cpp_exercise.h): into its own
// program, in the sandbox, which the hooks call; so it is live where Check can build it (Linux with
// bubblewrap). Elsewhere the panel says to rebuild shadowlab, as Check does (platform::grading_unavailable).
#pragma once

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "grading/lab.h"

namespace shadowlab {

class LiveCppExercise {
 public:
  LiveCppExercise() = default;
  LiveCppExercise(const LiveCppExercise&) = delete;
  LiveCppExercise& operator=(const LiveCppExercise&) = delete;
  ~LiveCppExercise();  // waits for a build under way (a build cannot be cancelled)

  // Reads the lab's C++ exercise files (the window calls it twice a second); when one differs from what
  // the hooks were last built from (at first: the copy compiled into the program), starts building hooks
  // from it. Nothing for the solution, or for a lab with no C++ exercise.
  // `wait`: a GL exercise's first build for this lab is made on this thread (0.4 s here), not in the
  // background.
  void poll(const Lab& lab, Impl impl, bool wait = false);
  // Hooks built from the edited file since the last call, for the window to set on its renderer.
  std::optional<Features> take_hooks();
  // Forgets what was built (another lab or implementation opened): the next poll starts over.
  void reset();
  bool building() const { return building_; }
  // What the panel says: the last build's error, or that the edited file is in use, or why it cannot be.
  std::string message() const;
  bool has_error() const;
  // The hooks in use failed while drawing (the student's program crashed or timed out on a call): the
  // window went back to the compiled copy; this file is not built again until it changes.
  void failed(const std::string& why);

 private:
  void start_build(const Lab& lab, Impl impl, std::size_t slot, const std::string& text);
  // A lab's GL exercise (Lab::gl_exercise_files: labs 0, 3, 5, 9): on the student's machine its file is built into a
  // shared library loaded into the window, whose renderer calls its functions (grading/live_gl.h) from
  // the next frame: from the first poll on, since the program's own are the solution's.
  void poll_gl(const Lab& lab, Impl impl, bool wait);
  void start_gl_build(const Lab& lab, Impl impl, const std::string& text, bool wait);
  // Hands out `last`'s hooks again when they were built from `text` (the renderer was reset since): no
  // new build. `built_text` is the slot's record of what the hooks in use were built from.
  bool reuse(const std::optional<std::pair<std::string, Features>>& last, const std::string& text, std::string& built_text);
  // Runs `job` on the worker (started on first use).
  void run_on_worker(std::function<void()> job);
  // A build's end, on the worker: its hooks handed out and remembered with `text`, or its error said.
  void finish_build(std::optional<Features> hooks, const std::string& error, const std::string& text, bool gl);

  const Lab* lab_ = nullptr;
  Impl impl_ = Impl::Exercise;
  std::string built_text_;  // the text the hooks in use were built from (empty: the compiled copy)
  // The last hooks built, and from what: handed out again, unbuilt, after a reset for the same lab.
  std::optional<std::pair<std::string, Features>> last_;
  std::string tried_text_;  // the text last tried, built or not (not tried again until it changes)
  std::string failed_text_;  // a text whose hooks failed while drawing (not tried again until it changes)
  // The same for the GL exercise's file (its built code is in the hooks' Features::gl_host).
  std::string gl_built_text_, gl_tried_text_;
  std::optional<std::pair<std::string, Features>> gl_last_;
  std::filesystem::path folder_;  // private, made on first use: one subfolder per build
  int generation_ = 0;
  // One worker for every build, alive as long as this: a student's program dies with the thread that
  // started it (grading/cpp_exercise.h, built_once), and the hooks call it from the window's frames.
  std::thread worker_;
  std::condition_variable wake_;
  std::function<void()> job_;  // guarded by mutex_
  bool stopping_ = false;      // guarded by mutex_
  std::atomic<bool> building_{false};
  mutable std::mutex mutex_;  // guards the three below, written by the build's thread
  std::optional<Features> ready_;
  std::string message_;
  bool in_use_ = false;
};

}  // namespace shadowlab
