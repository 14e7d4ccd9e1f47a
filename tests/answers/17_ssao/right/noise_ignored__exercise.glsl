// right: the noise ignored, one fixed helper vector for the frame (banding without the blur; the AO itself unchanged on average)
// expect: variant
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 helper = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t = normalize(helper - n * dot(helper, n));
  vec3 b = cross(n, t);
  mat3 tbn = mat3(t, b, n);
  float occlusion = 0.0;
  int count = ssao_sample_count();
  for (int i = 0; i < count; ++i) {
    vec3 s = p + tbn * ssao_kernel(i) * radius;
    float surface = ssao_scene_depth(s);
    float weight = range_check ? smoothstep(0.0, 1.0, radius / abs(p.z - surface)) : 1.0;
    occlusion += (surface >= s.z + bias ? 1.0 : 0.0) * weight;
  }
  return 1.0 - occlusion / float(count);
}
