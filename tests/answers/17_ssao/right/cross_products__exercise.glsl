// right: the frame from two cross products instead of Gram-Schmidt's subtraction, the samples' axes written out
// expect: variant
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 b = normalize(cross(n, noise));
  vec3 t = cross(b, n);
  float hidden = 0.0;
  for (int i = 0; i < ssao_sample_count(); ++i) {
    vec3 k = ssao_kernel(i);
    vec3 s = p + radius * (k.x * t + k.y * b + k.z * n);
    float z = ssao_scene_depth(s);
    if (z < s.z + bias) continue;
    hidden += range_check ? smoothstep(0.0, 1.0, radius / abs(p.z - z)) : 1.0;
  }
  return 1.0 - hidden / float(ssao_sample_count());
}
