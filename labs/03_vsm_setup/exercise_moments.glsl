// Lab 3 exercise, part 1: what the moments pass stores per texel. Edit this file; the lab reloads it
// when you save. Runs in the shadow pass's fragment shader (shaders/vsm/moments.frag), once per
// fragment of the surface nearest the light; z is gl_FragCoord.z, the depth in [0, 1].

// Returns (first moment, second moment), written into the RG32F colour attachment.
vec2 shadow_moments(float z) {
  // TODO: this is still the plain shadow map: depth in red, nothing in green. Store the two moments
  // E[z] and E[z^2] instead, so that filtering the texture averages them. Then add the slope term to
  // the second moment: one texel covers a spread of depths on a tilted surface, about
  // 1/4 * ((dz/dx)^2 + (dz/dy)^2) (dFdx, dFdy). Check: shadowlab check --lab 3 --impl exercise
  return vec2(z, 0.0);
}
