// What the PCSS of the spot and point lights share (shaders/shadow/pcss_spot.glsl, pcss_point.glsl): where
// their taps go, and where a tap's ray meets the receiver.
// The taps lie on a Vogel spiral (a golden-angle disk: no rows, so a wide region shows no staircase),
// turned per pixel by an interleaved-gradient angle (Jimenez 2014), so that neighbouring pixels sample
// between each other's taps.

// The search and the kernel reach at most this many texels from the point's own (a wide kernel of a few
// taps only shows noise).
const float PCSS_MAX_RADIUS_TEXELS = 64.0;
const float GOLDEN_ANGLE = 2.39996323;

// Tap i of n on a Vogel spiral in the unit disk, turned by `turn` radians.
vec2 vogel_tap(int i, int n, float turn) {
  float r = sqrt((float(i) + 0.5) / float(n));
  float a = float(i) * GOLDEN_ANGLE + turn;
  return r * vec2(cos(a), sin(a));
}

// Per-pixel angle from the pixel's position (Jimenez, "Next generation post processing in Call of Duty:
// Advanced Warfare", 2014): fixed for a pixel, so a still frame is still.
float interleaved_gradient_turn() {
  return 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// The point where the ray from the light with direction `dir` meets the receiver's plane (through p, normal
// n): each tap compares the stored depth with the receiver there, so a wide kernel needs no bias growing
// with its reach. p itself where the plane is seen edge-on or lies behind the light along that ray.
vec3 ray_on_receiver_plane(vec3 dir, vec3 p, vec3 n) {
  float facing = dot(dir, n);
  if (abs(facing) < 1e-4) return p;
  float t = dot(p - u_light_position, n) / facing;
  return t > 0.0 ? u_light_position + t * dir : p;
}
