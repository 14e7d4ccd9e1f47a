// wrong: the noise vector used as the tangent without removing its part along the normal (no Gram-Schmidt)
// expect: structure
// fails: *.open_error
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 t = normalize(noise);
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
