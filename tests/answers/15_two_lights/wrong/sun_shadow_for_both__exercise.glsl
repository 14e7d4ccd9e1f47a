// wrong: one shadow term for the scene: the sun's shadow darkens the flashlight's light too
// expect: partly-right
// fails: *.flashlight.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return (sun_lambert + flash_lambert) * sun_shadow;
}
