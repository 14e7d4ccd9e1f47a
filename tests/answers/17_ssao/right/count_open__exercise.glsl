// right: counts what each sample leaves open (1 minus its weighted occlusion) and averages that
// expect: variant
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  vec3 t = noise - dot(noise, n) * n;
  t /= length(t);
  mat3 frame = mat3(t, cross(n, t), n);
  int count = ssao_sample_count();
  float open = 0.0;
  for (int i = 0; i < count; ++i) {
    vec3 q = p + frame * (radius * ssao_kernel(i));
    float depth = ssao_scene_depth(q);
    float hidden = step(q.z + bias, depth);
    if (range_check) hidden *= smoothstep(0.0, 1.0, radius / abs(p.z - depth));
    open += 1.0 - hidden;
  }
  return open / float(count);
}
