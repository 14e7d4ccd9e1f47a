// Instructor tools drawn over the 3D view: the split view (left: the lab as the student runs it; right:
// the other implementation, the lab's defaults or a preset, in the same frame with a draggable divider),
// the magnifier on the cursor, and the always-visible line of per-pass GPU times.
#pragma once

#include <memory>

#include "app/panel_lab.h"
#include "renderer/gl_objects.h"
#include "renderer/renderer.h"

namespace shadowlab {

class SplitView {
 public:
  // Builds (lazily) the right side's renderer for `lab` as `state` says; call when the lab, the
  // implementation, the scene or the comparison changed. Returns false with `error` on a shader error.
  bool rebuild(const Lab& lab, Impl impl, const CompareState& state, const Scene& scene, std::string* error);
  void set_scene(const Scene& scene);
  void poll_shader_files();
  // The right side's values: the current ones (other implementation), the defaults, or a preset.
  ParamSet right_params(const Lab& lab, const ParamSet& current, const CompareState& state) const;
  // Label of each side, for the view and the panel.
  static std::string left_label(Impl impl, const CompareState& state);
  static std::string right_label(const Lab& lab, Impl impl, const CompareState& state);

  // Moves the divider when the user drags it (outside ImGui's windows). Returns true while the divider
  // owns the mouse, so the camera does not orbit at the same time.
  bool handle_divider(CompareState& state);
  // Renders the right side and copies the part right of the divider over framebuffer 0, which already
  // holds the left side; then draws the divider and the labels (ImGui background list).
  void compose(const ParamSet& right, const FrameRequest& request, const CompareState& state, const Lab& lab, Impl impl);
  const FrameStats* stats() const { return renderer_ ? &renderer_->stats() : nullptr; }
  // The right side's words over the view (its quads' labels, its legends); null when not split.
  const DebugAnnotations* annotations() const { return renderer_ ? &renderer_->annotations() : nullptr; }
  void set_timing(TimingMode mode) {
    if (renderer_) renderer_->set_timing(mode);
  }
  void release() { renderer_.reset(); }

 private:
  std::unique_ptr<Renderer> renderer_;
  bool dragging_ = false;
};

// A zoomed copy of the pixels around the cursor, shown in a corner window; nearest filtering so texels
// (aliasing, acne stripes) stay visible.
class Magnifier {
 public:
  // Copies the crop around the mouse from framebuffer 0 (call after the scene is drawn, before ImGui's).
  void capture(int fb_width, int fb_height);
  // The corner window with the zoomed image (call while building the ImGui frame).
  void draw() const;

 private:
  static constexpr int kCrop = 48;   // framebuffer pixels around the cursor
  static constexpr float kZoom = 5;  // on screen
  GlTexture texture_;
  GlFramebuffer fbo_;
};

// One line, top right, always visible: every pass's GPU time (and the right side's, when split).
void draw_pass_overlay(const FrameStats& left, const FrameStats* right);

}  // namespace shadowlab
