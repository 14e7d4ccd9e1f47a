// A bare ImGui context for CPU tests: no window, no GL. ImGui's real input state and draw lists, a
// 1280 x 720 display at 60 frames a second.
#pragma once

#include <gtest/gtest.h>

#include <imgui.h>

namespace shadowlab {

class BareImGuiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280, 720);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // NewFrame needs a built atlas, not a GPU texture
  }
  void TearDown() override { ImGui::DestroyContext(); }
};

}  // namespace shadowlab
