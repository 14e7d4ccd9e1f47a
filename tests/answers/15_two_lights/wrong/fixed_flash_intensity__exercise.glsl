// wrong: the flashlight weighted by the lab's default intensity again (0.8), tuned to the lab's own frame
// expect: tuned-to-scene
// fails: *.flashlight.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return sun_lambert * sun_shadow + 0.8 * flash_lambert * flash_shadow;
}
