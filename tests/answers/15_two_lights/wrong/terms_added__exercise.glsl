// wrong: each light's shadow term added to its Lambert term instead of multiplying it
// expect: compile-fine-but-wrong-formula
// fails: *.sun.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return (sun_lambert + sun_shadow) + (flash_lambert + flash_shadow);
}
