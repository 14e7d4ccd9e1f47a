// right: each light mixed from nothing to its full term by its own shadow term
// expect: variant
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  float lights[2] = float[2](mix(0.0, sun_lambert, sun_shadow), mix(0.0, flash_lambert, flash_shadow));
  return lights[0] + lights[1];
}
