// The direct light of a surface lit by two shadowed lights (lab 15's solution). Each light's Lambert
// term (n . l, its intensity, 0 where it does not reach) is multiplied by its OWN shadow term (1 lit,
// 0 shadowed), and the lights add: a point in the sun's shadow can still be lit by the flashlight.
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return sun_lambert * sun_shadow + flash_lambert * flash_shadow;
}
