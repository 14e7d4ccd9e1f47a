// Percentage-closer soft shadows for a point light with a size (shaders/shadow/pcss_point.glsl): the
// spot's steps (pcss_spot.cpp) around the ray to the point, on the six distance faces.
#include "renderer/shadow_tests/positional_pcss.h"

namespace shadowlab {

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() { return positional_pcss_test("pcss_point", "shaders/shadow/pcss_point.glsl"); }

}  // namespace shadowlab
