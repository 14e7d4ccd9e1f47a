// Lab 2 exercise: fit the directional light's orthographic projection to the scene's bounding box.
// Edit this function, save, and run: shadowlab check --lab 2 --impl exercise. On Linux Check builds your
// saved file on its own and the window builds it and draws with it; on Windows and macOS rebuild first
// (bash scripts/build).
#include "labs/02_ortho_fit/ortho_fit.h"

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  (void)bounds;
  // TODO: the tutorials' fixed box wastes the map on a small scene, clips a large one, and breaks when
  // the light points straight down (lookAt's up vector is parallel to the light). Replace it:
  //   1. C = the bounding box's centre: the centre of the light's view.
  //   2. Z = to_light (pointing TOWARD the light: the view looks down -Z, as lookAt's does, so points
  //      nearer the light get smaller depths); X, Y = any two unit vectors orthogonal to Z and to each other
  //      (orthonormal_basis(Z) in core/light.h gives a pair that never degenerates).
  //   3. Each half-length = the largest |(V - C) . axis| over the box's 8 corners (bounds.corner(i)).
  //   4. view = rows X, Y, Z with origin C; projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz).
  //      Fill image_x, image_y (= X, Y) and world_size (= 2 hx, 2 hy) too: the oracle needs them.
  return fixed_tutorial_ortho(to_light);
}

}  // namespace shadowlab
