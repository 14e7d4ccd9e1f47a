// `shadowlab labs`: the labs listed, with their parameters and presets on request.
#pragma once

namespace shadowlab {

// `shadowlab labs`: every lab, with --params its parameters, with --presets its presets (the artifact each
// provokes and the preset that fixes it); as JSON with --json.
int run_list_labs(bool show_params, bool json = false, bool show_presets = false);

}  // namespace shadowlab
