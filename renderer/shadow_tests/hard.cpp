// The basic shadow test (shaders/shadow/hard.glsl): one depth comparison against the nearest texel, the
// bias from "lab/bias.glsl". It reads no uniform of its own.
#include "renderer/shadow_test.h"

namespace shadowlab {

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() { return {"hard", "shaders/shadow/hard.glsl", {}, {}, {}}; }

}  // namespace shadowlab
