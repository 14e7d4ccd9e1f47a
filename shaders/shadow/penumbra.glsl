// The penumbra's width under a sun with a size (lab 16's solution). The sun is a disk of angular
// diameter light_size (degrees). Seen from a receiver point, a blocker's edge at distance
// (receiver_depth - blocker_depth) in front of it hides the disk gradually while the point moves across
// (receiver_depth - blocker_depth) x 2 tan(half the angle): the penumbra, in world units on a plane
// facing the light. It grows with the light's size and with the blocker-receiver distance, and shrinks
// to 0 (a hard shadow) as the light becomes a point or the blocker touches the receiver.
// receiver_depth, blocker_depth: distances along the light from the shadow map's near plane (world).
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) * 2.0 * tan(radians(light_size) * 0.5);
}
