#include "app/split_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "app/imgui_gl.h"

namespace shadowlab {

namespace {

Impl other(Impl impl) { return impl == Impl::Exercise ? Impl::Solution : Impl::Exercise; }

// Within this many pixels of the divider a click grabs it rather than orbiting the camera.
constexpr float kGrabPixels = 6.0f;

}  // namespace

bool SplitView::rebuild(const Lab& lab, Impl impl, const CompareState& state, const Scene& scene, std::string* error) {
  if (!state.split) {
    release();  // a second renderer's targets are not free; keep it only while it is shown
    return true;
  }
  if (!renderer_) {
    renderer_ = std::make_unique<Renderer>();
    renderer_->set_scene(scene);
  }
  const Impl right = state.with == CompareWith::OtherImpl ? other(impl) : impl;
  if (!renderer_->set_features(lab.hooks(right))) {
    if (error) *error = renderer_->shader_error();
    return false;
  }
  return true;
}

void SplitView::set_scene(const Scene& scene) {
  if (renderer_) renderer_->set_scene(scene);
}

void SplitView::poll_shader_files() {
  if (renderer_) renderer_->poll_shader_files();
}

ParamSet SplitView::right_params(const Lab& lab, const ParamSet& current, const CompareState& state) const {
  if (state.with == CompareWith::OtherImpl) return current;
  if (state.with == CompareWith::Defaults) return lab_params(lab);
  ParamSet p = current;  // a preset over the current values: what pressing its button would give
  if (state.preset >= 0 && state.preset < static_cast<int>(lab.presets.size()))
    for (const auto& [key, value] : lab.presets[static_cast<std::size_t>(state.preset)].values) p.set_from_string(key, value);
  return p;
}

std::string SplitView::left_label(Impl impl, const CompareState& state) {
  return state.with == CompareWith::OtherImpl ? impl_name(impl) : "your values";
}

std::string SplitView::right_label(const Lab& lab, Impl impl, const CompareState& state) {
  if (state.with == CompareWith::OtherImpl) return impl_name(other(impl));
  if (state.with == CompareWith::Defaults) return "lab defaults";
  if (state.preset >= 0 && state.preset < static_cast<int>(lab.presets.size()))
    return "preset: " + lab.presets[static_cast<std::size_t>(state.preset)].name;
  return "preset";
}

bool SplitView::handle_divider(CompareState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!state.split) {
    dragging_ = false;
    return false;
  }
  const float x = state.divider * io.DisplaySize.x;
  const bool near = std::abs(io.MousePos.x - x) <= kGrabPixels;
  if (!io.WantCaptureMouse && near && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) dragging_ = true;
  if (dragging_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_ = false;
  if (dragging_ && io.DisplaySize.x > 0) state.divider = std::clamp(io.MousePos.x / io.DisplaySize.x, 0.02f, 0.98f);
  if (dragging_ || (near && !io.WantCaptureMouse)) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  return dragging_;
}

void SplitView::compose(const ParamSet& right, const FrameRequest& request, const CompareState& state, const Lab& lab,
                        Impl impl) {
  if (!renderer_ || !state.split) return;
  // The right side is drawn offscreen and copied (its shadow passes must not meet the scissor).
  FrameRequest offscreen = request;
  offscreen.to_window = false;
  renderer_->render(right, offscreen);
  // The blit honours the scissor rectangle: only the part right of the divider is replaced.
  const int x0 = static_cast<int>(std::lround(state.divider * static_cast<float>(request.width)));
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, 0, request.width - x0, request.height);
  renderer_->present(0, request.width, request.height);
  glDisable(GL_SCISSOR_TEST);

  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float x = state.divider * io.DisplaySize.x;
  draw->AddLine(ImVec2(x, 0), ImVec2(x, io.DisplaySize.y), IM_COL32(0, 0, 0, 160), 5.0f);
  draw->AddLine(ImVec2(x, 0), ImVec2(x, io.DisplaySize.y), IM_COL32(255, 255, 255, 230), 2.0f);
  const float y = io.DisplaySize.y - 34.0f;
  auto label = [&](const std::string& text, float at_x) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    draw->AddRectFilled(ImVec2(at_x - 6, y - 4), ImVec2(at_x + size.x + 6, y + size.y + 4), IM_COL32(0, 0, 0, 170), 4.0f);
    draw->AddText(ImVec2(at_x, y), IM_COL32(255, 255, 255, 255), text.c_str());
  };
  const std::string left = "< " + left_label(impl, state);
  const std::string right_text = right_label(lab, impl, state) + " >";
  label(left, x - 14.0f - ImGui::CalcTextSize(left.c_str()).x);
  label(right_text, x + 14.0f);
}

void Magnifier::capture(int fb_width, int fb_height) {
  if (!texture_) {
    texture_ = GlTexture::create();
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kCrop, kCrop, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fbo_ = GlFramebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
  }
  const ImGuiIO& io = ImGui::GetIO();
  // ImGui's coordinates are window points, top-down; the framebuffer's are pixels, bottom-up.
  const float sx = io.DisplaySize.x > 0 ? static_cast<float>(fb_width) / io.DisplaySize.x : 1.0f;
  const float sy = io.DisplaySize.y > 0 ? static_cast<float>(fb_height) / io.DisplaySize.y : 1.0f;
  const int cx = static_cast<int>(io.MousePos.x * sx);
  const int cy = fb_height - static_cast<int>(io.MousePos.y * sy);
  const int x0 = std::clamp(cx - kCrop / 2, 0, std::max(0, fb_width - kCrop));
  const int y0 = std::clamp(cy - kCrop / 2, 0, std::max(0, fb_height - kCrop));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
  glBlitFramebuffer(x0, y0, x0 + kCrop, y0 + kCrop, 0, 0, kCrop, kCrop, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Magnifier::draw() const {
  if (!texture_) return;  // the first frame: nothing captured yet
  const ImGuiIO& io = ImGui::GetIO();
  const float side = kCrop * kZoom;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 10.0f, io.DisplaySize.y - 10.0f), ImGuiCond_Always, ImVec2(1, 1));
  ImGui::Begin("Magnifier", nullptr,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  // The texture's rows run bottom-up: flip v.
  gl_image(texture_.id(), ImVec2(side, side), ImVec2(0, 1), ImVec2(1, 0));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 c(at.x + side / 2, at.y + side / 2);
  draw->AddLine(ImVec2(c.x - 8, c.y), ImVec2(c.x + 8, c.y), IM_COL32(255, 60, 60, 255));
  draw->AddLine(ImVec2(c.x, c.y - 8), ImVec2(c.x, c.y + 8), IM_COL32(255, 60, 60, 255));
  ImGui::Text("x%.0f around the cursor (%.0f, %.0f)", kZoom, io.MousePos.x, io.MousePos.y);
  ImGui::End();
}

void draw_pass_overlay(const FrameStats& left, const FrameStats* right) {
  auto line = [](const FrameStats& s) {
    std::string text;
    double total = 0.0;
    char item[96];
    for (const auto& p : s.shown_passes()) {
      std::snprintf(item, sizeof item, "%.*s %.2f  ", static_cast<int>(p.name.size()), p.name.data(), p.gpu_ms);
      text += item;
      total += p.gpu_ms;
    }
    std::snprintf(item, sizeof item, "| GPU %.2f ms", total);
    return text + item;
  };
  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  float y = 8.0f;
  auto put = [&](const std::string& text) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const float x = io.DisplaySize.x - size.x - 12.0f;
    draw->AddRectFilled(ImVec2(x - 6, y - 3), ImVec2(x + size.x + 6, y + size.y + 3), IM_COL32(0, 0, 0, 170), 4.0f);
    draw->AddText(ImVec2(x, y), IM_COL32(230, 230, 230, 255), text.c_str());
    y += size.y + 8.0f;
  };
  put((right ? "left:  " : "") + line(left));
  if (right) put("right: " + line(*right));
}

}  // namespace shadowlab
