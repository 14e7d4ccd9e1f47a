// The shadow tests: what "lab/visibility.glsl" computes for a depth map (one comparison, PCF, PCSS). A
// test is an entry, registered like a lab: its name, its file, its parameters and how it binds its own
// uniforms on a lit program. Each is one file in renderer/shadow_tests/ defining
// `ShadowTest SHADOWLAB_SHADOW_TEST_MAKER()`; renderer/CMakeLists.txt lists the folder's files and
// generates the list (shadow_test_list.cpp), so adding a test touches only its own .cpp and its .glsl.
//
// A feature set selects one by name (Features::shadow_test): its file goes into the "lab/visibility.glsl"
// slot (unless the features name another file there: a student's version of that test), and only its
// bind runs when the lit pass draws.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/frame_light.h"
#include "core/params.h"
#include "renderer/gl.h"

namespace shadowlab {

struct DebugAnnotations;
// Uniforms the lit program may be compiled with as constants (name, value; ProgramDesc::constants).
using LitConstants = std::vector<std::pair<std::string, std::string>>;

// What a test's bind reads in one frame.
struct ShadowTestFrame {
  const ParamSet& params;
  const FrameLight& light;
  // A filter matched to the light's size (FrameLight::matched_filter_radius, pcf.match_light), in
  // texels, or -1 (the parameters decide).
  int matched_radius = -1;
  DebugAnnotations* annotations = nullptr;  // a false-colour view's legend goes here (null: none)
};

// Sets the test's uniforms on the lit program in use (it is current), from one frame's inputs.
using ShadowTestBind = std::function<void(const ShadowTestFrame&)>;

struct ShadowTest {
  std::string name;  // what Features::shadow_test and `render --shadow-test` name: "pcf"
  std::string file;  // its shader, under the data folder: "shaders/shadow/pcf.glsl"
  std::vector<ParamSpec> params;  // what it reads (a lab using it declares these, or a subset)
  // Looks its uniforms up on a lit program (by id, once per program build) and returns what sets them
  // each frame; empty: the test reads none of its own.
  std::function<ShadowTestBind(GLuint program)> resolve;
  // The uniforms among its own that the lit program may take as constants, appended to `out` (without
  // allocating once `out` held them); empty: none.
  std::function<void(const ShadowTestFrame&, LitConstants& out)> constants;
};

// Every registered test, by name (generated from renderer/shadow_tests/*.cpp).
const std::vector<ShadowTest>& shadow_tests();
// The test of this name; throws std::invalid_argument listing the names when there is none.
const ShadowTest& find_shadow_test(std::string_view name);
// Generated (build/renderer/shadow_test_list.cpp): each file's test.
std::vector<ShadowTest> folder_shadow_tests();

}  // namespace shadowlab
