// right: the two products as one dot product
// expect: variant
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return dot(vec2(sun_lambert, flash_lambert), vec2(sun_shadow, flash_shadow));
}
