#include "app/penumbra_view.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <imgui.h>

#include "app/imgui_gl.h"
#include "app/view_annotations.h"
#include "grading/check.h"
#include "oracle/soft_truth.h"

namespace shadowlab {

std::string penumbra_view_key(const ParamSet& params, const OrbitCamera& camera) {
  char text[160];
  std::snprintf(text, sizeof text, "|%.6g %.6g %.6g %.6g %.6g %.6g %.6g", camera.target.x, camera.target.y,
                camera.target.z, camera.distance, camera.yaw_deg, camera.pitch_deg, camera.fov_y_deg);
  return params.to_json().dump() + text;
}

PenumbraMeasure measure_penumbra(Renderer& renderer, const ParamSet& params, const OrbitCamera& camera,
                                 const Oracle& oracle, int width, int height) {
  const auto start = std::chrono::steady_clock::now();
  FrameRequest request;
  request.camera = camera;
  request.width = width;
  request.height = height;
  request.gbuffer = true;
  renderer.render(params, request);
  const GBuffer gbuffer = renderer.read_gbuffer();
  const std::vector<float> visibility = renderer.read_visibility();
  const SoftTruth truth = evaluate_soft(oracle, gbuffer, oracle_light(renderer), renderer.light_size(), kSoftTruthStrata);
  PenumbraMeasure m;
  m.width = width;
  m.height = height;
  m.metrics = compare_soft(truth, visibility);
  m.rgba = soft_diff_image(truth, visibility);
  m.light_size = params.get(param::light_size);
  m.sun = renderer.light_type() == LightType::Directional;
  m.view_key = penumbra_view_key(params, camera);
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

bool draw_penumbra_window(PenumbraPanelState& state, const std::string& current_key, bool interactive) {
  if (!state.open) return false;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(std::max(450.0f, display.x - 560.0f), 60.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::min(540.0f, display.x - 460.0f), std::min(460.0f, display.y - 80.0f)),
                           ImGuiCond_FirstUseEver);
  bool measure = false;
  if (ImGui::Begin("Penumbra error (against the exact soft shadow)", &state.open)) {
    if (interactive) {
      measure = ImGui::Button("Measure this view");
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Casts up to 256 rays per pixel toward the light's disk: a fraction of a second");
    }
    if (!state.error.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextWrapped("%s", state.error.c_str());
      ImGui::PopStyleColor();
    }
    if (!state.last) {
      ImGui::TextWrapped("Set light.size above 0 (the sun's angular diameter in degrees; a spot's or point "
                         "light's radius), then measure: grey is the fraction of the light each point truly "
                         "sees, red is drawn too dark, blue too light.");
    } else {
      const PenumbraMeasure& m = *state.last;
      if (!state.uploaded) {
        state.texture = make_texture_2d(GL_RGBA8, m.width, m.height, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
        glBindTexture(GL_TEXTURE_2D, state.texture.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m.width, m.height, GL_RGBA, GL_UNSIGNED_BYTE, m.rgba.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        state.uploaded = true;
      }
      if (m.light_size <= 0.0f)
        ImGui::TextWrapped("light.size was 0: the truth is a hard shadow (no penumbra). Raise it to grade the "
                           "penumbra.");
      else
        ImGui::Text("light.size %.3g (%s)", m.light_size, m.sun ? "the sun's angular diameter, degrees" : "radius");
      const double penumbra_share =
          m.metrics.valid_pixels ? 100.0 * static_cast<double>(m.metrics.penumbra_pixels) / static_cast<double>(m.metrics.valid_pixels) : 0.0;
      ImGui::Text("mean error %.4f = too dark %.4f + too light %.4f", m.metrics.mae, m.metrics.too_dark, m.metrics.too_light);
      ImGui::Text("in the penumbra (%.1f %% of the pixels): %.4f", penumbra_share, m.metrics.mae_penumbra);
      if (m.view_key != current_key) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
        ImGui::TextWrapped("The view or a parameter has changed since: measure again.");
        ImGui::PopStyleColor();
      }
      // The colour bar of the picture below (the mapping soft_diff_image uses, renderer/debug_annotations.h).
      const ImVec2 at = ImGui::GetCursorScreenPos();
      const float legend_width = std::min(ImGui::GetContentRegionAvail().x, 30.0f * ImGui::GetFontSize());
      const float legend_height = draw_colour_legend(ImGui::GetWindowDrawList(), penumbra_error_legend(), at,
                                                     legend_width, ImGui::GetFontSize(), false);
      ImGui::Dummy(ImVec2(legend_width, legend_height));
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      const float scale = std::min(avail.x / static_cast<float>(m.width), std::max(avail.y, 60.0f) / static_cast<float>(m.height));
      gl_image(state.texture.id(), ImVec2(static_cast<float>(m.width) * scale, static_cast<float>(m.height) * scale));
    }
  }
  ImGui::End();
  return measure;
}

}  // namespace shadowlab
