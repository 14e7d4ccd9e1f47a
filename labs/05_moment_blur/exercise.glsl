// Lab 5 exercise: blur the moments with a separable Gaussian. Edit this file; the lab reloads it when
// you save. It runs in shaders/vsm/blur.frag, twice per shadow map: once with direction (1, 0) over the
// moments (the X pass, into the ping-pong texture), then with (0, 1) over the X pass's result (the Y
// pass, back into the moments texture). Lab 4's light-bleeding fix stays on.
uniform int u_blur_radius;   // slider "Blur radius (texels)": 1..16 here (radius 0 runs no pass)
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

// moments: the texture to blur; texel: this fragment's integer texel; direction: (1, 0) or (0, 1).
// Returns the blurred (E[z], E[z^2]) for this texel.
vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  // TODO: this reads one texel, so both passes copy the moments unchanged. Average the 2r + 1 texels
  // texel + i * direction, i = -r..r, with Gaussian weights exp(-i^2 / (2 sigma^2)) divided by their
  // sum. Clamp the coordinates to [0, textureSize - 1] (clamp to edge) and read with texelFetch:
  // GLSL requires textureOffset's offset to be a constant expression, which a loop variable is not.
  // Then run: shadowlab check --lab 5 --impl exercise
  return texelFetch(moments, texel, 0).rg;
}
