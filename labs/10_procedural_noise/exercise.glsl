// Lab 10: gradient noise. Write gradient_noise(p) and the octave sum noise_octaves(p); see the lab's text.
//
// The gradients: an N x N texture (RGBA8, repeat-wrapped, nearest), one gradient per lattice corner.
// The corner with integer coordinates i has the gradient stored in texel i (the texture repeats:
// texture(u_noise_gradients, (i + 0.5) / N).xy with N = textureSize(u_noise_gradients, 0).x), decoded
// from [0, 1] to [-1, 1] (times 2, minus 1). The noise repeats every N units.
uniform sampler2D u_noise_gradients;

float gradient_noise(vec2 p) {
  // TODO: the four corners around p; from each, the vector to p dotted with the corner's gradient;
  // the four products blended with a smooth fade of the position inside the cell.
  return 0.0;
}

float noise_octaves(vec2 p) {
  // TODO: noise(p) + 0.5 noise(2p) + 0.25 noise(4p).
  return gradient_noise(p);
}
