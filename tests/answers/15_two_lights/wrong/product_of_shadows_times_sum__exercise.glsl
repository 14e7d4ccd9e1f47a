// wrong: both shadow terms multiply the sum of both lights (a point shadowed from either light gets no light)
// expect: partly-right
// fails: *.sun.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return (sun_lambert + flash_lambert) * sun_shadow * flash_shadow;
}
