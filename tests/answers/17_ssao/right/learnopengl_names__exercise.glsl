// right: LearnOpenGL's loop as printed (fragPos, samplePos, sampleDepth, rangeCheck), the range check always computed and switched by a multiply
// expect: variant
float ssao_open(vec3 fragPos, vec3 normal, vec3 randomVec, float radius, float bias, bool range_check) {
  vec3 tangent = normalize(randomVec - normal * dot(randomVec, normal));
  vec3 bitangent = cross(normal, tangent);
  mat3 TBN = mat3(tangent, bitangent, normal);
  float occlusion = 0.0;
  int kernelSize = ssao_sample_count();
  for (int i = 0; i < kernelSize; ++i) {
    vec3 samplePos = TBN * ssao_kernel(i);
    samplePos = fragPos + samplePos * radius;
    float sampleDepth = ssao_scene_depth(samplePos);
    float rangeCheck = smoothstep(0.0, 1.0, radius / abs(fragPos.z - sampleDepth));
    float use = range_check ? 1.0 : 0.0;
    occlusion += (sampleDepth >= samplePos.z + bias ? 1.0 : 0.0) * mix(1.0, rangeCheck, use);
  }
  occlusion = 1.0 - (occlusion / float(kernelSize));
  return occlusion;
}
