#version 330 core
// One direction of the separable Gaussian blur of the moments (lab 5). The program is built twice,
// with BLUR_DIRECTION ivec2(1, 0) for the X pass and ivec2(0, 1) for the Y pass: a 2D Gaussian is
// the product of two 1D ones, so (2r + 1) taps twice replace (2r + 1)^2 taps once. The moments are
// blurred, never the visibility: the average of moments is again a valid pair of moments, so
// Chebyshev's bound then describes the whole filter region.
#include "lab/blur.glsl"

uniform sampler2D u_moments;

// Written to both pairs of a four-moment target (EVSM): the renderer draws twice, reading and writing
// one pair each time (MomentsPass::blur). A two-channel target keeps the first pair.
layout(location = 0) out vec4 o_moments;

void main() { o_moments = blur_moments(u_moments, ivec2(gl_FragCoord.xy), BLUR_DIRECTION).xyxy; }
