#include "renderer/pass_timer.h"

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

PassTimer::PassTimer()
    : timer_(GlQuery::create()), samples_(GlQuery::create()), software_rasterizer_(is_software_rasterizer()) {}

void PassTimer::record(const char* name, FrameStats& stats, GLuint64 query_ns, double wall_ms) const {
  const double gpu_ms = static_cast<double>(query_ns) * 1e-6;
  const bool use_wall = software_rasterizer_ || gpu_ms > wall_ms + 1.0;
  stats.passes.push_back({name, use_wall ? wall_ms : gpu_ms, use_wall, wall_ms});
}

}  // namespace shadowlab
