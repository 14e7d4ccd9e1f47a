// right: each light added only where its own shadow test says it is lit
// expect: variant
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  float direct = 0.0;
  if (sun_shadow > 0.5) direct += sun_lambert;
  if (flash_shadow > 0.5) direct += flash_lambert;
  return direct;
}
