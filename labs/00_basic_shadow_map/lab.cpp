// Lab 0: the basic shadow map, the starting point before the numbered exercises.
// Demonstrates: a depth-only pass from the light, the [-1,1] -> [0,1] bias matrix, one depth comparison
// per fragment with a constant bias, and the debug quad showing the shadow map.
#include "labs/lab.h"

namespace shadowlab {

Lab make_lab_basic_shadow_map() {
  Lab lab;
  lab.number = 0;
  lab.slug = "basic_shadow_map";
  lab.title = "Basic shadow map";
  lab.summary = "Two passes: depth from the light, then one depth comparison per pixel.";
  lab.presets = {
      {"acne", "No bias: surfaces shadow themselves in stripes.", {{"shadow.bias", "0"}}},
      {"peter-panning", "A huge bias: shadows detach from the objects casting them.", {{"shadow.bias", "0.05"}}},
      {"tutorial", "The tutorial's constant bias of 0.005.", {{"shadow.bias", "0.005"}}},
  };
  lab.hooks = [](Impl) { return LabHooks{}; };
  return lab;
}

}  // namespace shadowlab
