// Lab 15: two shadowed lights, the sun and a flashlight.
//
// The lit pass calls this once per pixel with each light's terms:
//   sun_lambert    the sun's n . l times its intensity (0 where it does not reach the surface)
//   sun_shadow     the sun's shadow term from its ortho map: 1 lit, 0 shadowed
//   flash_lambert  the flashlight's n . l times its intensity (0 outside its cone)
//   flash_shadow   the flashlight's shadow term from its own perspective map: 1 lit, 0 shadowed
// and returns the direct light on the surface (the ambient is added outside).
//
// TODO: the flashlight is not in yet: only the sun lights the scene. Add the flashlight's light,
// shadowed by its own shadow term.
float combine_lights(float sun_lambert, float sun_shadow, float flash_lambert, float flash_shadow) {
  return sun_lambert * sun_shadow;
}
