// Times passes and counts what they write, for FrameStats.
//
// A pass is timed by a GL_TIME_ELAPSED query read at once, and by the wall time between two glFinish
// calls around it. On a GPU the query is the figure (a GPU time cannot exceed the wall time around it; if
// it does, the wall time is used and the pass marked). On llvmpipe the "GPU" is the CPU, so the wall time
// is the pass's true cost, and its queries are not: they read 0.01-0.3 ms for passes that draw into the
// framebuffer the previous pass drew into (the stencil shadow volumes' three passes, a lit pass after a
// skipped shadow pass) against 1.1-16.6 ms of wall time, and the first query of a new context reads the
// machine's uptime (3.3e6 ms). There every pass uses the wall time and is marked.
#pragma once

#include <chrono>

#include "renderer/frame_stats.h"
#include "renderer/gl_objects.h"

namespace shadowlab {

class PassTimer {
 public:
  PassTimer();  // needs a current GL context

  // Runs the pass and appends its timing to stats.passes.
  template <typename F>
  void time(const char* name, FrameStats& stats, F&& pass) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, timer_.id());
    pass();
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(timer_.id(), GL_QUERY_RESULT, &ns);
    glFinish();
    record(name, stats, ns, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }

  // Runs draws and returns how many fragments passed the depth test (texels written, overdraw included).
  template <typename F>
  long count_samples(F&& draws) {
    glBeginQuery(GL_SAMPLES_PASSED, samples_.id());
    draws();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(samples_.id(), GL_QUERY_RESULT, &samples);
    return static_cast<long>(samples);
  }

 private:
  void record(const char* name, FrameStats& stats, GLuint64 query_ns, double wall_ms) const;

  GlQuery timer_;
  GlQuery samples_;
  bool software_rasterizer_ = false;  // llvmpipe and the like: the wall time is the pass's cost
};

}  // namespace shadowlab
