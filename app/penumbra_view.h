// The window's "Penumbra error" view: the current frame against the exact penumbra of the light's size
// (oracle/soft_truth.h), as the diff image the checks write (metrics.h soft_diff_image: grey is the true
// visible fraction, red where drawn too dark, blue where drawn too light) and its figures. The truth
// costs 17 to 256 shadow rays per pixel (0.05-0.4 s for 640 x 360 on llvmpipe's machine), so it is
// measured when asked (a button, or `render --panel --penumbra`), never every frame; the window says
// when the view has changed since.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/gl_objects.h"
#include "oracle/metrics.h"
#include "oracle/oracle.h"
#include "core/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

struct PenumbraMeasure {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // soft_diff_image, row 0 at the top
  SoftMetrics metrics;
  float light_size = 0.0f;  // the light.size parameter as measured (sun: degrees; spot, point: radius)
  bool sun = true;          // the light was directional (light_size is an angle)
  double seconds = 0.0;     // render, read-back and truth together
  std::string view_key;     // what was measured (parameters and camera): the window compares it with now
};

// Renders `params` from `camera` at width x height with the G-buffer, evaluates the soft truth of the
// renderer's light with its size (size 0: the hard truth, as fractions 0 and 1) against `oracle` (built
// from renderer.scene()) and compares. Throws what Oracle or evaluate_soft throw.
PenumbraMeasure measure_penumbra(Renderer& renderer, const ParamSet& params, const OrbitCamera& camera,
                                 const Oracle& oracle, int width, int height);

// A key for "the same view": the parameters' values and the camera.
std::string penumbra_view_key(const ParamSet& params, const OrbitCamera& camera);

struct PenumbraPanelState {
  bool open = false;
  std::optional<PenumbraMeasure> last;
  std::string error;  // why the last measure failed
  GlTexture texture;  // last->rgba, uploaded when shown
  bool uploaded = false;
};

// Draws the window when open; returns true when the user asked to measure (the app then calls
// measure_penumbra and stores the result in state.last). `current_key`: penumbra_view_key of the view
// now. `interactive` false: no button (documentation pictures).
bool draw_penumbra_window(PenumbraPanelState& state, const std::string& current_key, bool interactive);

}  // namespace shadowlab
