// Lab 16 exercise: the penumbra's width for percentage-closer soft shadows (PCSS). Edit this file; the
// lab reloads it when you save.
//
// The sun is a disk of angular diameter light_size, in DEGREES (the "Light size" slider). PCSS has found
// the blockers in front of the point and their mean distance; you estimate how wide the penumbra is
// there, and PCSS filters over that width.
//   receiver_depth: the point's distance along the light from the shadow map's near plane (world units)
//   blocker_depth:  the blockers' mean distance, measured the same way (smaller: nearer the light)
//   returns:        the penumbra's width on a plane facing the light (world units)
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  // TODO: 0 is a point light's answer: a hard shadow, whatever the sun's size. Draw the two rays from
  // the blocker's edge to the two sides of the sun's disk: how far apart are they when they reach the
  // receiver? Think about what makes the penumbra wider, and what makes it vanish. GLSL's radians() and
  // tan() may help. Then run: shadowlab check --lab 16 --impl exercise
  return 0.0;
}
