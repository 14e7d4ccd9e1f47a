// Lab 15 exercise: the flashlight's shadow map follows the node that carries it.
// Edit this function, save, and run: shadowlab check --lab 15 --impl exercise. On Linux Check builds your
// saved file on its own and the window builds it and draws with it; on Windows and macOS rebuild first
// (bash scripts/build).
#include <glm/gtc/matrix_transform.hpp>

#include "labs/15_two_lights/flashlight_fit.h"

namespace shadowlab {

// node_to_world: the node's world transform, rigid (columns: its X, Y, Z axes and its position). The
//   flashlight sits at the node's origin and shines along the node's -Z axis.
// cone_deg: the half-angle of the flashlight's cone, in degrees.
// bounds: the scene's box (every caster and receiver is inside it).
// Return the view (world -> the light's eye space, looking down -Z) and the perspective projection of
// its shadow map; only `view` and `projection` are read.
LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  (void)node_to_world;
  (void)cone_deg;
  (void)bounds;
  // TODO: this is a tutorial's spot matrix, fixed once: it does not follow the node, its field of view
  // is not the cone's, its near and far planes are typed in, and its lookAt has no basis when the light
  // points straight down. Replace it:
  //   1. The view: the inverse of the node's rigid transform, or a basis built from the node's position
  //      and its -Z axis (orthonormal_basis in core/light.h never degenerates).
  //   2. The projection: glm::perspective with the whole cone in the square map (aspect 1).
  //   3. Near and far fitted to what the light can see: the depths along the light's axis of the box's
  //      8 corners (bounds.corner(i)); near the least of them, far the greatest (or the distance to the
  //      farthest corner), each with a small margin, and near never below far / kMaxFarOverNear.
  LightView v;
  v.view = glm::lookAt(glm::vec3(0.0f, 4.0f, 6.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  v.projection = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 25.0f);
  return v;
}

}  // namespace shadowlab
