// Lab 17 exercise: screen-space ambient occlusion. Edit this file; the lab reloads it when you save.
//
// Return the share of the hemisphere around the point that is OPEN (1: nothing nearby hides the sky,
// 0: fully enclosed), estimated with the kernel's samples tested against the depth buffer.
//   p, n:        the point and its unit normal, in VIEW space (the camera sits at the origin, looking down -z)
//   noise:       a random vector in the screen's plane (z = 0) from the 4 x 4 noise texture, different for
//                each pixel of a 4 x 4 tile
//   radius:      the hemisphere's radius (the "AO radius" slider; view-space units are world units)
//   bias:        how far in front of a sample the depth buffer's surface must be to hide it
//   range_check: when true, an occluder much farther from p than radius must count less (or not at all)
// What the renderer hands you:
//   int ssao_sample_count()      how many samples to take (the "AO samples" slider)
//   vec3 ssao_kernel(int i)      sample i in TANGENT space: inside the unit hemisphere z >= 0, z along the normal
//   float ssao_scene_depth(vec3 q)  the view-space z of the visible surface where the view-space point q
//                                   projects on the screen (a very negative number where there is none)
//   mat4 u_view                  world -> view (p and n are already in view space)
float ssao_open(vec3 p, vec3 n, vec3 noise, float radius, float bias, bool range_check) {
  // TODO: build a frame (tangent, bitangent, normal) around n from the noise vector (Gram-Schmidt),
  // turn each kernel sample into a view-space point within radius of p, and count the samples the depth
  // buffer hides (its surface nearer the camera than the sample, by more than bias). Then run:
  //   shadowlab check --lab 17 --impl exercise
  return 1.0;
}
