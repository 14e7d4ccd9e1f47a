// wrong: the two lights averaged instead of added
// expect: partly-right
// fails: *.sun.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return 0.5 * (sun_lambert * sun_shadow + flash_lambert * flash_shadow);
}
