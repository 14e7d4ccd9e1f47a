// wrong: the brighter light wins: right for each light alone, wrong where both reach
// expect: tuned-to-scene
// fails: *.combined.wrong_share
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return max(sun_lambert * sun_shadow, flash_lambert * flash_shadow);
}
