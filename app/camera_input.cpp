#include "app/camera_input.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <imgui.h>

namespace shadowlab {

namespace {
constexpr float kDegreesPerPixel = 0.3f;
constexpr float kZoomPerNotch = 0.9f;
}  // namespace

bool orbit_pan_zoom(OrbitCamera& camera, const Bounds& scene) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return false;
  bool moved = false;
  const ImVec2 d = io.MouseDelta;
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (d.x != 0.0f || d.y != 0.0f)) {
    camera.yaw_deg -= d.x * kDegreesPerPixel;
    camera.pitch_deg = std::clamp(camera.pitch_deg + d.y * kDegreesPerPixel, -85.0f, 85.0f);
    moved = true;
  }
  const bool pan = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f);
  if (pan && (d.x != 0.0f || d.y != 0.0f) && io.DisplaySize.y > 0) {
    // Move the target in the view plane so the point under the cursor follows it: one pixel is the
    // view's height at the target's distance divided by the window's height.
    const glm::mat4 view = camera.view();
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
    const float per_pixel = 2.0f * camera.distance * std::tan(glm::radians(camera.fov_y_deg) * 0.5f) / io.DisplaySize.y;
    camera.target += (-d.x * right + d.y * up) * per_pixel;
    moved = true;
  }
  if (io.MouseWheel != 0.0f) {
    // Closer by 10 % a notch, down to a thousandth of the scene's size. (It was clamped to twice the near
    // plane, which is recomputed from the distance: from the framed view a notch in moved the camera out.)
    const float closest = scene.empty() ? 1e-3f : 1e-3f * glm::length(scene.extent());
    camera.distance = std::max(closest, camera.distance * std::pow(kZoomPerNotch, io.MouseWheel));
    moved = true;
  }
  if (moved && !scene.empty()) {
    const float radius = 0.5f * glm::length(scene.extent());
    const float centre = glm::length(camera.eye() - scene.center());
    camera.near_plane = std::max(centre - radius, 1e-3f * camera.distance);
    camera.far_plane = centre + radius;
  }
  return moved;
}

}  // namespace shadowlab
