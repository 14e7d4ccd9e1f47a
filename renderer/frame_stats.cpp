#include "renderer/frame_stats.h"

namespace shadowlab {

nlohmann::json FrameStats::to_json() const {
  nlohmann::json passes_json = nlohmann::json::object();
  nlohmann::json wall_clock = nlohmann::json::array();
  for (const auto& p : passes) {
    passes_json[std::string(p.name)] = p.gpu_ms;
    if (p.wall_clock) wall_clock.push_back(std::string(p.name));
  }
  return {{"gpu_ms", passes_json}, {"gpu_ms_from_wall_clock", wall_clock}, {"cpu_ms", cpu_ms}, {"frames", frames}, {"shadow_passes", shadow_passes},
          {"flashlight_shadow_passes", flashlight_shadow_passes},
          {"moments_passes", moments_passes}, {"blur_passes", blur_passes}, {"cube_faces", cube_faces},
          {"stencil_passes", stencil_passes}, {"draws", draws}, {"casters_culled", casters_culled},
          {"shadow_texels_written", shadow_texels_written}, {"moments_negative_variance", moments_negative_variance},
          {"gl_finishes", gl_finishes}, {"blocking_query_reads", blocking_query_reads}};
}

}  // namespace shadowlab
