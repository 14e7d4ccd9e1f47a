// wrong: the darker of the two shadow terms multiplies the sum of both lights
// expect: partly-right
// fails: *.sun.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return (sun_lambert + flash_lambert) * min(sun_shadow, flash_shadow);
}
