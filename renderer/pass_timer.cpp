#include "renderer/pass_timer.h"

#include <algorithm>
#include <string>

namespace shadowlab {

namespace {

bool is_software_rasterizer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
         name.find("SwiftShader") != std::string::npos;
}

}  // namespace

TimingMode interactive_timing(bool timers_work, bool pass_line_shown) {
  if (timers_work) return TimingMode::Queries;
  return pass_line_shown ? TimingMode::Exact : TimingMode::Off;
}

PassTimer::PassTimer()
    : timer_(GlQuery::create()), samples_(GlQuery::create()), software_rasterizer_(is_software_rasterizer()) {
  pool_.reserve(64);
  free_timers_.reserve(64);
  free_samples_.reserve(64);
  pending_.reserve(64);
}

void PassTimer::set_mode(TimingMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  // Results timed another way are not mixed with the new mode's.
  for (const auto& p : pending_) free_list(p.samples).push_back(p.query);
  pending_.clear();
}

void PassTimer::record(const char* name, FrameStats& stats, GLuint64 query_ns, double wall_ms) const {
  const double gpu_ms = static_cast<double>(query_ns) * 1e-6;
  const bool use_wall = software_rasterizer_ || gpu_ms > wall_ms + 1.0;
  stats.passes.push_back({name, use_wall ? wall_ms : gpu_ms, use_wall, wall_ms, true});
}

GLuint PassTimer::start_async(std::string_view name, bool samples, GLenum target) {
  std::vector<GLuint>& free = free_list(samples);
  if (free.empty()) {
    pool_.push_back(GlQuery::create());
    free.push_back(pool_.back().id());
  }
  const GLuint query = free.back();
  free.pop_back();
  pending_.push_back({query, name, frame_, samples});
  glBeginQuery(target, query);
  return query;
}

void PassTimer::drop_frame(long frame) {
  auto end = pending_.begin();
  for (; end != pending_.end() && end->frame == frame; ++end) free_list(end->samples).push_back(end->query);
  pending_.erase(pending_.begin(), end);
}

void PassTimer::begin_frame(FrameStats& stats) {
  ++frame_;
  // Oldest frame first: publish a frame once every one of its queries is available; stop at the first
  // that is not (results arrive in order).
  while (!pending_.empty()) {
    const long frame = pending_.front().frame;
    if (frame_ - frame > kFramesInFlight) {
      drop_frame(frame);
      continue;
    }
    bool ready = true;
    for (const auto& p : pending_) {
      if (p.frame != frame) break;
      GLuint available = GL_FALSE;
      glGetQueryObjectuiv(p.query, GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available) {
        ready = false;
        break;
      }
    }
    if (!ready) return;
    stats.timed_passes.clear();
    for (const auto& p : pending_) {
      if (p.frame != frame) break;
      GLuint64 value = 0;
      glGetQueryObjectui64v(p.query, GL_QUERY_RESULT, &value);  // available: does not wait
      if (p.samples) {
        stats.shadow_texels_written += static_cast<long>(value);
      } else {
        const double ms = static_cast<double>(value) * 1e-6;
        stats.timed_passes.push_back({p.name, ms, false, 0.0, true});
      }
    }
    stats.timed_frames_ago = frame_ - frame;
    drop_frame(frame);
  }
}

}  // namespace shadowlab
