// wrong: view and world mixed up: the normal taken to world space (transpose of the view) while the point stays in view space
// expect: units
// fails: *.open_error
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 nw = normalize(transpose(mat3(u_view)) * n);
  vec3 t = normalize(noise - nw * dot(noise, nw));
  vec3 b = cross(nw, t);
  mat3 tbn = mat3(t, b, nw);
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
