// GTAO's integral (Jimenez et al. 2016, "Practical Realtime Strategies for Accurate Indirect Occlusion"):
// the cosine-weighted share of the hemisphere around n that no surface within u_radius hides, the same
// quantity as the AO truth (oracle/ao_truth.h), estimated under a height-field assumption (everything
// below a horizon is occluded). Per slice (a plane through the eye's ray, along a screen direction):
//   1. the horizons on both sides: the highest (nearest the eye's ray) of u_steps samples of the depth
//      buffer per side, spread over the radius projected on the screen; a sample farther than u_radius
//      from p does not count (the truth counts occluders within the radius only);
//   2. the angle of the normal projected into the slice, the horizons clamped to its hemisphere;
//   3. the cosine-weighted visible arc between the horizons in closed form, weighed by the projected
//      normal's length (the slices' average of it is the hemisphere's integral).
//   uv, p, n:  the pixel's centre, its view-space point and unit normal (the camera looks down -z)
//   jitter:    x rotates the slices, y offsets the steps (both in [0, 1), from the noise)
float gtao_open(vec2 uv, vec3 p, vec3 n, vec2 jitter) {
  vec3 v = normalize(-p);
  vec2 size = vec2(textureSize(u_position, 0));
  // The radius on the screen, in pixels (the projection's vertical scale at the point's depth).
  float radius_px = u_radius * u_projection[1][1] * 0.5 * size.y / max(-p.z, 1e-4);
  float step_px = max(radius_px / float(u_steps), 1.0);
  float visible = 0.0;
  for (int i = 0; i < u_directions; ++i) {
    float phi = (float(i) + jitter.x) * kPi / float(u_directions);
    vec2 dir = vec2(cos(phi), sin(phi));
    // The slice's frame: its direction across the eye's ray, and the axis normal to the slice.
    vec3 d = vec3(dir, 0.0);
    vec3 ortho = d - dot(d, v) * v;
    vec3 axis = normalize(cross(ortho, v));
    vec3 np = n - axis * dot(n, axis);
    float np_length = length(np);
    if (np_length < 1e-4) continue;
    float cos_n = clamp(dot(np, v) / np_length, -1.0, 1.0);
    float angle_n = sign(dot(ortho, np)) * acos(cos_n);
    // Horizons as cosines with the eye's ray; the lowest is the tangent plane's (nothing hides).
    float horizon_cos0 = cos(angle_n + 0.5 * kPi), horizon_cos1 = cos(angle_n - 0.5 * kPi);
    for (int j = 0; j < u_steps; ++j) {
      vec2 offset = dir * (float(j) + jitter.y + 0.5) * step_px / size;
      vec4 s0 = gtao_position(uv + offset), s1 = gtao_position(uv - offset);
      vec3 delta0 = s0.xyz - p, delta1 = s1.xyz - p;
      float dist0 = length(delta0), dist1 = length(delta1);
      if (s0.w > 0.5 && dist0 > 1e-5 && dist0 <= u_radius) horizon_cos0 = max(horizon_cos0, dot(delta0, v) / dist0);
      if (s1.w > 0.5 && dist1 > 1e-5 && dist1 <= u_radius) horizon_cos1 = max(horizon_cos1, dot(delta1, v) / dist1);
    }
    // Side 0 lies along +dir (positive angles), side 1 along -dir; each clamped to n's hemisphere.
    float h0 = angle_n + clamp(acos(clamp(horizon_cos0, -1.0, 1.0)) - angle_n, -0.5 * kPi, 0.5 * kPi);
    float h1 = angle_n + clamp(-acos(clamp(horizon_cos1, -1.0, 1.0)) - angle_n, -0.5 * kPi, 0.5 * kPi);
    float sin_n = sin(angle_n);
    float arc0 = (cos_n + 2.0 * h0 * sin_n - cos(2.0 * h0 - angle_n)) * 0.25;
    float arc1 = (cos_n + 2.0 * h1 * sin_n - cos(2.0 * h1 - angle_n)) * 0.25;
    visible += np_length * (arc0 + arc1);
  }
  return visible / float(u_directions);
}
