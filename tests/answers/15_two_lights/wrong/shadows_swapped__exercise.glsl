// wrong: each light multiplied by the other light's shadow term
// expect: partly-right
// fails: *.sun.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return sun_lambert * flash_shadow + flash_lambert * sun_shadow;
}
