// Percentage-closer soft shadows for a spot light with a size (shaders/shadow/pcss_spot.glsl): the sun's
// three steps (pcss.cpp) measured in the spot's perspective, on a Vogel spiral turned per pixel.
#include "renderer/shadow_tests/positional_pcss.h"

namespace shadowlab {

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() { return positional_pcss_test("pcss_spot", "shaders/shadow/pcss_spot.glsl"); }

}  // namespace shadowlab
