// wrong: the kernel not scaled by the radius (a unit hemisphere whatever the slider says)
// expect: units
// fails: *.darkening_share_cap
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 t = normalize(noise - n * dot(noise, n));
  vec3 b = cross(n, t);
  mat3 tbn = mat3(t, b, n);
  float occlusion = 0.0;
  int count = ssao_sample_count();
  for (int i = 0; i < count; ++i) {
    vec3 s = p + tbn * ssao_kernel(i);
    float surface = ssao_scene_depth(s);
    float weight = range_check ? smoothstep(0.0, 1.0, radius / abs(p.z - surface)) : 1.0;
    occlusion += (surface >= s.z + bias ? 1.0 : 0.0) * weight;
  }
  return 1.0 - occlusion / float(count);
}
