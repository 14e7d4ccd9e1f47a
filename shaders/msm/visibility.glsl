// The moment-shadow-map test (lab 14): the four-moment Hamburger bound of Peters & Klein 2015
// (Moment Shadow Mapping, I3D; their algorithm 2), on the linearly filtered power moments, at the
// biased receiver depth. 1 lit, 0 shadowed, soft in between.
#include "lab/bias.glsl"

uniform float u_msm_moment_bias;  // slider "MSM moment bias" (alpha)

// The share of the filter region's depth distribution in front of z, bounded from above over every
// distribution with these four moments (the Hamburger problem's extreme one, three depths: z and the
// two roots of a quadratic); 1 - that is the light reaching z.
float msm_hamburger(vec4 moments, float z) {
  // The moment bias: mix with the moments of a distribution on [0, 1] keeps the Hankel matrix positive
  // definite in float32 (0.5 for every moment, as in the paper's 4MSM).
  vec4 b = mix(moments, vec4(0.5), u_msm_moment_bias);
  // Cholesky factorisation of the Hankel matrix B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] (LDL^T,
  // only its non-trivial entries).
  float L32D22 = -b.x * b.y + b.z;
  float D22 = -b.x * b.x + b.y;
  float squared_depth_variance = -b.y * b.y + b.w;
  float D33D22 = squared_depth_variance * D22 - L32D22 * L32D22;
  float inv_D22 = 1.0 / D22;
  float L32 = L32D22 * inv_D22;
  // Solve B c = (1, z, z^2): forward substitution, scaling, backward substitution.
  vec3 c = vec3(1.0, z, z * z);
  c.y -= b.x;
  c.z -= b.y + L32 * c.y;
  c.y *= inv_D22;
  c.z *= D22 / D33D22;
  c.y -= L32 * c.z;
  c.x -= dot(c.yz, b.xy);
  // The two other support points: roots of c.x + c.y x + c.z x^2.
  float p = c.y / c.z;
  float q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z1 = -p * 0.5 - r;
  float z2 = -p * 0.5 + r;
  // The weight of the support points in front of z.
  vec4 s = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
  float quotient = (s.x * z2 - b.x * (s.x + z2) + b.y) / ((z2 - s.y) * (z - z1));
  return clamp(s.z + s.w * quotient, 0.0, 1.0);
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec4 moments = texture(u_shadow_map, s.xy);
  return 1.0 - msm_hamburger(moments, s.z - shadow_bias(n_dot_l));
}
