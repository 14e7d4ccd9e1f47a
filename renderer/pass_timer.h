// Times passes and counts what they write, for FrameStats, in one of three modes (TimingMode).
//
// Exact (the default; benchmarks, headless runs, tests): a GL_TIME_ELAPSED query read at once, and the
// wall time between two glFinish calls around the pass. On a GPU the query is the figure (a GPU time
// cannot exceed the wall time around it; if it does, the wall time is used and the pass marked). On
// llvmpipe the "GPU" is the CPU, so the wall time is the pass's true cost, and its queries are not: they
// read 0.01-0.3 ms for passes that draw into the framebuffer the previous pass drew into (the stencil
// shadow volumes' three passes, a lit pass after a skipped shadow pass) against 1.1-16.6 ms of wall time,
// and the first query of a new context reads the machine's uptime (3.3e6 ms). There every pass uses the
// wall time and is marked. The price: two glFinish and a blocking query read per pass.
//
// Queries (the window, where the driver's timers work): each pass's timer query goes into a small ring
// and is read frames later, once GL says its result is available; nothing is ever waited for. A frame's
// times appear in FrameStats::timed_passes when all of its queries have come back.
//
// Off (the window on a driver whose timers are useless, while no pass-time line is shown): no timing.
//
// Sample counts (GL_SAMPLES_PASSED) are read at once in Exact mode and through the ring otherwise (they
// reach FrameStats::shadow_texels_written a few frames late).
#pragma once

#include <chrono>
#include <string_view>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/gl_objects.h"

namespace shadowlab {

enum class TimingMode { Exact, Queries, Off };

// The interactive frame's mode: queries wherever the driver's timers work; where they are useless
// (llvmpipe), exact timing only while the pass-time line is shown, otherwise none.
TimingMode interactive_timing(bool timers_work, bool pass_line_shown);

class PassTimer {
 public:
  PassTimer();  // needs a current GL context

  void set_mode(TimingMode mode);
  TimingMode mode() const { return mode_; }
  // False on software rasterisers (llvmpipe and the like), whose timer queries measure nothing useful.
  bool timers_work() const { return !software_rasterizer_; }

  // Starts a frame: collects, without waiting, the ring's results that have come back.
  void begin_frame(FrameStats& stats);

  // Runs the pass and appends it to stats.passes (with its time in Exact mode).
  template <typename F>
  void time(const char* name, FrameStats& stats, F&& pass) {
    if (mode_ != TimingMode::Exact) {
      const GLuint query = mode_ == TimingMode::Queries ? start_async(name, false, GL_TIME_ELAPSED) : 0;
      pass();
      if (query) glEndQuery(GL_TIME_ELAPSED);
      stats.passes.push_back({name, 0.0, false, 0.0, false});
      return;
    }
    finish(stats);
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, timer_.id());
    pass();
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(timer_.id(), GL_QUERY_RESULT, &ns);
    ++stats.blocking_query_reads;
    finish(stats);
    record(name, stats, ns, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }

  // Runs draws and returns how many fragments passed the depth test (texels written, overdraw included);
  // outside Exact mode it returns 0 and the count reaches stats.shadow_texels_written when it comes back.
  template <typename F>
  long count_samples(FrameStats& stats, F&& draws) {
    if (mode_ != TimingMode::Exact) {
      start_async("", true, GL_SAMPLES_PASSED);
      draws();
      glEndQuery(GL_SAMPLES_PASSED);
      return 0;
    }
    glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
    draws();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &samples);
    ++stats.blocking_query_reads;
    return static_cast<long>(samples);
  }

 private:
  // One query in flight: what it measures and the frame it belongs to.
  struct Pending {
    GLuint query = 0;
    std::string_view name;  // a pass name (string literals only), empty for a sample count
    long frame = 0;
    bool samples = false;
  };
  static constexpr long kFramesInFlight = 4;  // older results are dropped, never waited for

  void finish(FrameStats& stats) const {
    glFinish();
    ++stats.gl_finishes;
  }
  void record(const char* name, FrameStats& stats, GLuint64 query_ns, double wall_ms) const;
  GLuint start_async(std::string_view name, bool samples, GLenum target);
  void drop_frame(long frame);

  GlQuery timer_;
  GlQuery samples_;
  bool software_rasterizer_ = false;  // llvmpipe and the like: the wall time is the pass's cost
  TimingMode mode_ = TimingMode::Exact;
  long frame_ = 0;
  // A query object keeps the target it was first begun with (beginning it with another is
  // GL_INVALID_OPERATION), so timers and sample counters are recycled through their own free lists.
  std::vector<GLuint>& free_list(bool samples) { return samples ? free_samples_ : free_timers_; }

  std::vector<GlQuery> pool_;  // every query the ring has made; grows to its steady size, then stays
  std::vector<GLuint> free_timers_;
  std::vector<GLuint> free_samples_;
  std::vector<Pending> pending_;  // oldest first
};

}  // namespace shadowlab
