// wrong: the flashlight added, its shadow forgotten
// expect: half-done
// fails: *.flashlight.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return sun_lambert * sun_shadow + flash_lambert;
}
