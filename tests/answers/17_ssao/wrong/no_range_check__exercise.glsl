// wrong: no range check: every sample behind a surface counts, however far that surface is from the point
// expect: skipped-half
// fails: *.halo_width_px
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 t = normalize(noise - n * dot(noise, n));
  vec3 b = cross(n, t);
  mat3 tbn = mat3(t, b, n);
  float occlusion = 0.0;
  for (int i = 0; i < ssao_sample_count(); ++i) {
    vec3 s = p + tbn * ssao_kernel(i) * radius;
    if (ssao_scene_depth(s) >= s.z + bias) occlusion += 1.0;
  }
  return 1.0 - occlusion / float(ssao_sample_count());
}
