// Parameters declared once: parsing, ranges, JSON, invalidation bits.
#include <gtest/gtest.h>

#include "core/params.h"
#include "core/placement.h"
#include "renderer/renderer.h"
#include "core/technique_params.h"
#include "core/vsm_params.h"

namespace shadowlab {
namespace {

TEST(Params, RendererDefaultsAndAssignments) {
  ParamSet p(renderer_param_specs());
  EXPECT_FLOAT_EQ(p.get_float("shadow.bias"), 0.005f);
  EXPECT_EQ(p.get_choice("shadow.map_size"), "1024");
  EXPECT_EQ(p.apply_assignment("shadow.bias=0.01"), kInvalidatesNothing);
  EXPECT_FLOAT_EQ(p.get_float("shadow.bias"), 0.01f);
  EXPECT_NE(p.apply_assignment("shadow.map_size=2048") & kInvalidatesTargets, 0u);
  EXPECT_EQ(p.get_choice("shadow.map_size"), "2048");
  EXPECT_EQ(p.apply_assignment("shadow.map_size=2048"), kInvalidatesNothing);  // unchanged: nothing to redo
  EXPECT_NE(p.apply_assignment("light.elevation=10") & kInvalidatesShadowMap, 0u);
  p.apply_assignment("view.debug_quad=off");
  EXPECT_FALSE(p.get_bool("view.debug_quad"));
}

std::string error_of(ParamSet& p, const std::string& assignment) {
  try {
    p.apply_assignment(assignment);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Params, BadInputNamesTheValidChoices) {
  ParamSet p(renderer_param_specs());
  const std::string unknown = error_of(p, "shadow.bais=0.1");
  EXPECT_NE(unknown.find("unknown parameter 'shadow.bais'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("shadow.bias"), std::string::npos) << "lists the valid keys: " << unknown;
  const std::string range = error_of(p, "shadow.bias=5");
  EXPECT_NE(range.find("[0, 0.1]"), std::string::npos) << range;
  const std::string choice = error_of(p, "shadow.map_size=1000");
  EXPECT_NE(choice.find("256 512 1024 2048 4096"), std::string::npos) << choice;
  EXPECT_NE(error_of(p, "shadow.bias=abc").find("not a number"), std::string::npos);
  EXPECT_NE(error_of(p, "shadow.bias=nan").find("out of range"), std::string::npos);
  EXPECT_NE(error_of(p, "noequals").find("key=value"), std::string::npos);
  EXPECT_FLOAT_EQ(p.get_float("shadow.bias"), 0.005f) << "a rejected value leaves the old one";
}

TEST(Params, JsonRoundTrip) {
  ParamSet a(renderer_param_specs());
  a.apply_assignment("shadow.cull=front");
  a.apply_assignment("light.azimuth=120");
  ParamSet b(renderer_param_specs());
  EXPECT_TRUE(b.apply_json(a.to_json()).empty());
  EXPECT_EQ(b.to_json(), a.to_json());
  EXPECT_EQ(a.to_json()["shadow.cull"], "front");
  const auto problems = b.apply_json(nlohmann::json{{"nope", 1}, {"shadow.bias", 7.0}});
  EXPECT_EQ(problems.size(), 2u);
}

TEST(Params, DeclareReplacesDefault) {
  ParamSet p(renderer_param_specs());
  ParamSpec spec = *p.find("light.elevation");
  spec.default_value = 10.0;
  p.declare(spec);
  EXPECT_FLOAT_EQ(p.get_float("light.elevation"), 10.0f);
  EXPECT_EQ(std::count_if(p.specs().begin(), p.specs().end(), [](const ParamSpec& s) { return s.key == "light.elevation"; }), 1);
}

// Reallocated targets hold no shadow map yet: a parameter that invalidates them must invalidate the map
// too (the renderer redraws the map from the kInvalidatesShadowMap bit alone). The lit program's
// constants (PCF's) pick another lit program and leave the map as it is.
TEST(Params, TargetBitImpliesTheShadowMapBit) {
  std::vector<ParamSpec> all = renderer_param_specs();
  for (auto group : {vsm_param_specs(), light_param_specs(), pcf_param_specs(), point_param_specs(), volume_param_specs()})
    all.insert(all.end(), group.begin(), group.end());
  int with_targets = 0;
  std::vector<std::string> programs;
  for (const auto& spec : all) {
    if (spec.invalidates & kInvalidatesTargets) {
      EXPECT_NE(spec.invalidates & kInvalidatesShadowMap, 0u) << spec.key;
      ++with_targets;
    }
    if (spec.invalidates & kInvalidatesPrograms) programs.push_back(spec.key);
  }
  EXPECT_EQ(with_targets, 6) << "shadow.map_size, shadow.depth_format, vsm.format, vsm.blur_radius, vsm.match_light, "
                                "light.type";
  EXPECT_EQ(programs, (std::vector<std::string>{"light.type", "pcf.kernel", "pcf.hardware", "pcf.match_light",
                                                "pcf.match_distance"}));
}

TEST(Params, ValuesInvalidatingListsTheDeclaredInputsInOrder) {
  ParamSet p(renderer_param_specs());
  p.declare({"test.input", "An input", ParamKind::Float, 0.5, 0.0, 1.0, "", {}, kInvalidatesShadowMap});
  p.apply_assignment("light.azimuth=120");
  const auto inputs = p.values_invalidating(kInvalidatesShadowMap);
  std::vector<std::string> keys;
  for (const auto& [key, value] : inputs) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"light.azimuth", "light.elevation", "shadow.map_size", "shadow.depth_format",
                                            "shadow.cull", "shadow.cull_casters", "scene.ground", "scene.blend_casts",
                                            "scene.local_origin", "scene.offset_x",
                                            "scene.offset_y", "scene.offset_z", "scene.scale", "test.input"}));
  EXPECT_EQ(inputs.front().second, 120.0);
  EXPECT_EQ(inputs.back().second, 0.5);
  EXPECT_EQ(p.values_invalidating(kInvalidatesTargets).size(), 2u);
}

// A handle reads the set's value when the set declares its key (a feature set's own default included),
// else the default declared with the handle; it reads as its type; it writes only a declared key.
TEST(Params, HandlesReadTheSetOrTheDeclaredDefault) {
  ParamSet p(renderer_param_specs());
  EXPECT_EQ(p.get(param::shadow_bias), 0.005f);
  p.apply_assignment("shadow.bias=0.01");
  EXPECT_EQ(p.get(param::shadow_bias), 0.01f);
  EXPECT_EQ(p.get(param::shadow_map_size), "1024");
  EXPECT_EQ(p.index(param::shadow_map_size), 2);
  EXPECT_TRUE(p.get(param::view_debug_quad));
  // Keys the set does not declare: the handles' declared defaults.
  EXPECT_EQ(p.get(param::vsm_blur_radius), 0);
  EXPECT_EQ(p.get(param::vsm_format), "RG32F");
  EXPECT_EQ(p.index(param::vsm_format), 0);
  EXPECT_EQ(p.get(param::light_type), "directional");
  EXPECT_EQ(p.get(param::pcss_filter_samples), 8);
  // A feature set's own default wins over the handle's.
  ParamSpec elevation = param::light_elevation.spec();
  elevation.default_value = 10.0;
  p.declare(elevation);
  EXPECT_EQ(p.get(param::light_elevation), 10.0f);
  EXPECT_EQ(param::light_elevation.spec().default_value, 50.0) << "the handle keeps its own";
  // Writes through a handle, a choice by name.
  EXPECT_NE(p.set(param::shadow_map_size, "2048") & kInvalidatesTargets, 0u);
  EXPECT_EQ(p.get_choice("shadow.map_size"), "2048");
  EXPECT_EQ(p.set(param::view_debug_quad, false), kInvalidatesNothing);
  EXPECT_FALSE(p.get_bool("view.debug_quad"));
  EXPECT_THROW(p.set(param::vsm_blur_radius, 3), std::out_of_range) << "the set does not declare it";
  EXPECT_THROW(p.set(param::shadow_map_size, "1000"), std::invalid_argument);
  // A double handle keeps what float would round (the placement's offsets far from the origin).
  ParamSet placed(placement_param_specs());
  placed.set(param::scene_offset_x, 1e6 + 0.125);
  EXPECT_EQ(placed.get(param::scene_offset_x), 1e6 + 0.125);
}

TEST(Params, AHandleOfTheWrongTypeIsRejected) {
  EXPECT_THROW(FloatParam({"test.count", "A count", ParamKind::Int, 0.0, 0.0, 1.0, "", {}}), std::logic_error);
  EXPECT_THROW(BoolParam({"test.mode", "A mode", ParamKind::Choice, 0.0, 0.0, 1.0, "", {}}), std::logic_error);
  EXPECT_NO_THROW(IntParam({"test.count", "A count", ParamKind::Int, 0.0, 0.0, 1.0, "", {}}));
  EXPECT_NO_THROW(DoubleParam({"test.offset", "An offset", ParamKind::Float, 0.0, 0.0, 1.0, "", {}}));
}

// The value a set has for a spec it may not declare (what a one-off value's "was" reads).
TEST(Params, ValueOrDefaultOfASpec) {
  ParamSet p(renderer_param_specs());
  p.apply_assignment("shadow.bias=0.02");
  EXPECT_EQ(p.value_or_default(param::shadow_bias.spec()), 0.02);
  EXPECT_EQ(p.value_or_default(param::vsm_bleed_delta.spec()), 0.125);
}

}  // namespace
}  // namespace shadowlab
