// The renderer's own parameters, declared once (CPU only, so CPU tests and tools can read them).
#include "renderer/params.h"

namespace shadowlab {

std::vector<ParamSpec> renderer_param_specs() {
  const unsigned shadow = kInvalidatesShadowMap;
  return {
      {"light.azimuth", "Light azimuth (deg)", ParamKind::Float, 35.0, 0.0, 360.0,
       "Direction of the light around the vertical axis.", {}, shadow},
      {"light.elevation", "Light elevation (deg)", ParamKind::Float, 50.0, 1.0, 90.0,
       "Height of the light above the ground plane: low values give long shadows and grazing angles (acne).", {}, shadow},
      {"shadow.map_size", "Shadow map size", ParamKind::Choice, 2.0, 0.0, 4.0,
       "Texels per side of the shadow map: more texels, finer shadow edges, more memory and time.",
       {"256", "512", "1024", "2048", "4096"}, shadow | kInvalidatesTargets},
      {"shadow.depth_format", "Depth format", ParamKind::Choice, 1.0, 0.0, 2.0,
       "Precision of the stored depth: 16-bit fixed point shows acne sooner than 24-bit or 32-bit float.",
       {"16", "24", "32F"}, shadow | kInvalidatesTargets},
      {"shadow.bias", "Constant bias", ParamKind::Float, 0.005, 0.0, 0.1,
       "Subtracted from the fragment's light-space depth before the comparison: too small gives acne, too "
       "large peter-panning. In depth units of the light's projection ([0, 1]).", {}, kInvalidatesNothing, true},
      {"shadow.slope_bias", "Slope bias", ParamKind::Float, 0.0, 0.0, 20.0,
       "Extra bias that grows with the surface's tilt away from the light, in shadow-map texels per unit of "
       "tan(angle of incidence).", {}},
      {"shadow.cull", "Shadow pass culling", ParamKind::Choice, 0.0, 0.0, 2.0,
       "Which faces the shadow pass skips. Culling front faces stores back faces, moving acne to faces that "
       "are unlit anyway (needs closed meshes).", {"none", "front", "back"}, shadow},
      {"view.ambient", "Ambient", ParamKind::Float, 0.25, 0.0, 1.0, "Light that reaches shadowed surfaces too.", {}},
      {"view.debug_quad", "Show shadow map", ParamKind::Bool, 1.0, 0.0, 1.0,
       "A quad in the corner shows what the light sees (the shadow map's depths).", {}},
  };
}

}  // namespace shadowlab
