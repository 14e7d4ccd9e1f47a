// The solution of lab 17: the share of the hemisphere's samples around a view-space point that no
// surface of the depth buffer hides (Crytek's SSAO, with LearnOpenGL's normal-oriented hemisphere).
//   p, n:        the point and its unit normal, in view space (the camera looks down -z)
//   noise:       a random vector in the screen's plane, from the 4 x 4 noise texture
//   radius:      the hemisphere's radius (view-space units, the same as the world's)
//   bias:        how far in front of a sample the surface must be to hide it
//   range_check: weigh each occluder down when it is farther than radius from p
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  // A frame around n (Gram-Schmidt): the noise vector made perpendicular to n rotates the kernel per pixel.
  vec3 t = normalize(noise - n * dot(noise, n));
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
