// The mouse moves the camera: left drag orbits, right or middle drag pans, the wheel zooms. Nothing
// happens while ImGui wants the mouse (a slider being dragged, the cursor over the panel).
#pragma once

#include "core/light.h"
#include "core/scene.h"

namespace shadowlab {

// Applies this frame's mouse input to `camera`; returns true when it moved. The near and far planes
// follow so the scene's bounds stay between them, as tight as they allow (depth precision).
bool orbit_pan_zoom(OrbitCamera& camera, const Bounds& scene);

}  // namespace shadowlab
