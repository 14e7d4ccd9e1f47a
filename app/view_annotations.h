// The words over the 3D view (renderer/debug_annotations.h): each debug quad's label, above its quad
// (hiding none of the map), and each false-colour view's legend, a colour bar with its units and the
// values at its ends.
// Drawn with ImGui by the window and by `render --panel` alike, at the panel's text size (the user's Text
// size x the monitor's scale) times kAnnotationTextScale, so that they grow with it.
#pragma once

#include <imgui.h>

#include "renderer/debug_annotations.h"

namespace shadowlab {

// The labels' and legends' text against the panel's body text: a little larger, for the back row.
inline constexpr float kAnnotationTextScale = 1.25f;

// Draws `annotations` of a frame fb_width x fb_height (framebuffer pixels; ImGui's display may differ by
// its framebuffer scale) over the part of the view from x_begin to x_end (display coordinates; a split
// view's side), into ImGui's background draw list (the panel stays over it). Legends stack up from the
// bottom right of that part, above the debug quads and their labels.
void draw_view_annotations(const DebugAnnotations& annotations, int fb_width, int fb_height, float x_begin, float x_end);

// Draws one legend with its top left at `pos`, `width` wide, text at `font_size` (the default font),
// into `draw` (null: only measures); returns its height. `backdrop`: a dark box behind it (over the view).
float draw_colour_legend(ImDrawList* draw, const ColourLegend& legend, ImVec2 pos, float width, float font_size,
                         bool backdrop);

}  // namespace shadowlab
