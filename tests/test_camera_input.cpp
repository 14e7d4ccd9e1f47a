// The mouse as a person uses it, through ImGui's real input state (a bare ImGui context, no window):
// a left drag over the view orbits, a right drag pans, the wheel zooms, and nothing moves the camera
// while the cursor is over an ImGui window (the panel) or a widget holds the mouse.
#include <gtest/gtest.h>

#include <imgui.h>

#include "app/camera_input.h"
#include "tests/imgui_fixture.h"
#include "core/scene.h"

namespace shadowlab {
namespace {

class CameraInputTest : public BareImGuiTest {
 protected:
  void SetUp() override {
    BareImGuiTest::SetUp();
    scene = make_default_scene().bounds();
    camera = OrbitCamera::framing(scene);
  }

  // One frame: the mouse at (x, y) with the given buttons and wheel, a panel window at (10, 10) 420 x
  // 700 as the app draws it; returns whether the camera moved.
  bool frame(float x, float y, bool left, bool right, float wheel = 0.0f) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(x, y);  // ImGui 1.86: the state a platform backend writes each frame
    io.MouseDown[0] = left;
    io.MouseDown[1] = right;
    io.MouseWheel = wheel;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::SetNextWindowSize(ImVec2(420, 700));
    ImGui::Begin("panel");
    ImGui::Text("the lab's panel");
    ImGui::End();
    const bool moved = orbit_pan_zoom(camera, scene);
    ImGui::Render();
    return moved;
  }

  Bounds scene;
  OrbitCamera camera;
};

TEST_F(CameraInputTest, LeftDragOverTheViewOrbits) {
  frame(800, 400, false, false);
  frame(800, 400, true, false);
  const float yaw = camera.yaw_deg, pitch = camera.pitch_deg;
  EXPECT_TRUE(frame(860, 380, true, false));
  EXPECT_NEAR(camera.yaw_deg, yaw - 60 * 0.3f, 1e-3f);
  EXPECT_NEAR(camera.pitch_deg, pitch - 20 * 0.3f, 1e-3f);
  EXPECT_FALSE(frame(860, 380, false, false)) << "released: no motion";
}

TEST_F(CameraInputTest, RightDragPansAndWheelZooms) {
  frame(800, 400, false, false);
  frame(800, 400, false, true);
  const glm::vec3 target = camera.target;
  EXPECT_TRUE(frame(830, 400, false, true));
  EXPECT_GT(glm::distance(camera.target, target), 0.0f);
  frame(830, 400, false, false);
  const float distance = camera.distance;
  EXPECT_TRUE(frame(830, 400, false, false, 1.0f));
  EXPECT_NEAR(camera.distance, distance * 0.9f, 1e-3f) << "one notch in: 10 % closer";
  for (int notch = 0; notch < 200; ++notch) frame(830, 400, false, false, 1.0f);
  EXPECT_LT(camera.distance, 0.01f * distance) << "zooming in keeps going in";
  EXPECT_GT(camera.distance, 0.0f);
  EXPECT_GT(camera.near_plane, 0.0f);
  EXPECT_TRUE(frame(830, 400, false, false, -1.0f));
  EXPECT_GT(camera.distance, 0.0f) << "and back out";
}

TEST_F(CameraInputTest, NothingMovesWhileTheMouseIsOverThePanel) {
  frame(200, 300, false, false);  // over the panel
  frame(200, 300, true, false);
  const float yaw = camera.yaw_deg, distance = camera.distance;
  EXPECT_FALSE(frame(260, 320, true, false));
  EXPECT_FALSE(frame(260, 320, true, false, 1.0f));
  EXPECT_EQ(camera.yaw_deg, yaw);
  EXPECT_EQ(camera.distance, distance);
  // A drag that starts on the panel keeps belonging to ImGui even when it leaves it.
  EXPECT_FALSE(frame(900, 320, true, false));
  EXPECT_EQ(camera.yaw_deg, yaw);
}

}  // namespace
}  // namespace shadowlab
