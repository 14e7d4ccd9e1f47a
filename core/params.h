// Parameters, declared once: key, label, default, range, tooltip and what a change invalidates. The
// same declaration drives every front end (a slider, a `key=value` assignment, presets, JSON) and the
// renderer's decisions of what to redo (see Invalidates).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowlab {

enum class ParamKind { Float, Int, Bool, Choice };

// What must be redone when a parameter changes. The renderer redraws the shadow map exactly when a
// declared parameter with kInvalidatesShadowMap changed (or the light, scene, targets or programs did),
// so a parameter the shadow pass reads must declare it; one the lit pass or a view reads must not, or
// every change of it costs a shadow pass. The other bits say why (the passes check their targets and
// variants themselves). kInvalidatesTargets always comes with kInvalidatesShadowMap: new targets hold
// no map yet. kInvalidatesPrograms alone marks a parameter that a lit program is compiled for (a
// constant, see ShadowPass::lit_constants): a change picks another program, the shadow map stays.
enum Invalidates : unsigned {
  kInvalidatesNothing = 0,
  kInvalidatesShadowMap = 1u << 0,  // shadow, moment and blur passes
  kInvalidatesTargets = 1u << 1,    // render targets must be reallocated (size, format)
  kInvalidatesPrograms = 1u << 2,   // shader variants must be rebuilt (defines)
};

struct ParamSpec {
  std::string key;  // "shadow.bias"; what assignments and JSON use
  std::string label;
  ParamKind kind = ParamKind::Float;
  double default_value = 0.0;
  double min = 0.0;
  double max = 1.0;
  std::string tooltip;
  std::vector<std::string> choices;  // Choice: value is an index into this list
  unsigned invalidates = kInvalidatesNothing;
  bool logarithmic = false;  // slider hint for ranges spanning decades
};

// A parameter's handle, declared once beside its family's table (the table is built from the handles):
// the spec (key, default, range, what a change invalidates) and the type a read returns. Code reads and
// writes a parameter through its handle (ParamSet::get, ParamSet::set), so it cannot name a key nobody
// declared; the string API below is for the front ends that take keys from the user (assignments, JSON,
// the sliders). T is float or double (a Float parameter, read at the precision its code computes in), int,
// bool or Choice (a choice's name, const std::string&).
struct Choice {};

template <class T>
struct ParamValue;  // what a Param<T> reads as and the kind it must be declared with
template <class Type, ParamKind Kind>
struct ParamValueOf {
  using type = Type;
  static constexpr ParamKind kind = Kind;
};
template <>
struct ParamValue<float> : ParamValueOf<float, ParamKind::Float> {};
template <>
struct ParamValue<double> : ParamValueOf<double, ParamKind::Float> {};
template <>
struct ParamValue<int> : ParamValueOf<int, ParamKind::Int> {};
template <>
struct ParamValue<bool> : ParamValueOf<bool, ParamKind::Bool> {};
template <>
struct ParamValue<Choice> : ParamValueOf<const std::string&, ParamKind::Choice> {};

template <class T>
class Param {
 public:
  // Throws std::logic_error when the spec's kind is not T's (a handle declared with the wrong type: the
  // program stops at start-up, before any test or frame).
  explicit Param(ParamSpec spec) : spec_(std::move(spec)) {
    if (spec_.kind != ParamValue<T>::kind)
      throw std::logic_error("parameter " + spec_.key + " declared with the wrong type");
  }
  const ParamSpec& spec() const { return spec_; }
  const std::string& key() const { return spec_.key; }

 private:
  ParamSpec spec_;
};
using FloatParam = Param<float>;
using DoubleParam = Param<double>;
using IntParam = Param<int>;
using BoolParam = Param<bool>;
using ChoiceParam = Param<Choice>;

// The specs of these handles, in the order given: a family's table, or the subset a feature set declares.
template <class... T>
std::vector<ParamSpec> specs_of(const Param<T>&... handles) {
  return {handles.spec()...};
}

class ParamSet {
 public:
  ParamSet() = default;
  explicit ParamSet(std::vector<ParamSpec> specs);

  // Adds a spec (or replaces the one with the same key, e.g. a feature set changing a default).
  void declare(ParamSpec spec);

  const std::vector<ParamSpec>& specs() const { return specs_; }
  // Lookups take a string_view: reading a parameter every frame allocates nothing (a key longer than
  // std::string's small buffer would, made into a std::string from a literal).
  const ParamSpec* find(std::string_view key) const;

  double get(std::string_view key) const;  // throws std::out_of_range for an unknown key
  // The value when the set declares the spec's key, else the spec's default (one lookup).
  double value_or_default(const ParamSpec& spec) const;
  // A handle's value: the set's when it declares the key (a feature set may have changed the default),
  // else the handle's declared default.
  template <class T>
  typename ParamValue<T>::type get(const Param<T>& param) const {
    if constexpr (std::is_same_v<T, Choice>) {
      const ParamSpec& spec = param.spec();
      const ParamSpec* own = find(spec.key);
      return (own ? *own : spec).choices.at(static_cast<std::size_t>(value_or_default(spec)));
    } else if constexpr (std::is_same_v<T, bool>) {
      return value_or_default(param.spec()) != 0.0;
    } else {
      return static_cast<T>(value_or_default(param.spec()));
    }
  }
  // A choice's index into its list (what a shader's uniform takes).
  int index(const Param<Choice>& param) const { return static_cast<int>(value_or_default(param.spec())); }
  float get_float(std::string_view key) const { return static_cast<float>(get(key)); }
  int get_int(std::string_view key) const { return static_cast<int>(get(key)); }
  bool get_bool(std::string_view key) const { return get(key) != 0.0; }
  const std::string& get_choice(std::string_view key) const;

  // Sets a value, clamped to nothing: out of range is an error. Returns the invalidation bits of the
  // change (0 when the value did not change). Throws std::invalid_argument with a one-line message.
  unsigned set(const std::string& key, double value);
  // Parses "value" for the key's kind (numbers, true/false/on/off/1/0, a choice's name).
  unsigned set_from_string(const std::string& key, const std::string& text);
  // Through a handle (the set must declare it: throws std::out_of_range otherwise). A choice by name.
  template <class T>
  unsigned set(const Param<T>& param, typename ParamValue<T>::type value) {
    if constexpr (std::is_same_v<T, Choice>) return set_from_string(param.key(), value);
    else return set(param.key(), static_cast<double>(value));
  }
  // Parses "key=value"; the message lists the valid keys when the key is unknown.
  unsigned apply_assignment(const std::string& assignment);
  void reset_to_defaults();

  std::string format(const std::string& key) const;  // the value as an assignment would take it
  nlohmann::json to_json() const;                      // {"key": value, ...} with choices by name
  // Applies what it can from JSON written by to_json(); returns one message per rejected entry.
  std::vector<std::string> apply_json(const nlohmann::json& values);
  // Key and value of every parameter whose invalidation bits include any of `bits`, in declaration
  // order: what the work those bits stand for depends on (the renderer compares them frame to frame).
  std::vector<std::pair<std::string, double>> values_invalidating(unsigned bits) const;
  // The same into `out`, reusing its storage (no allocation when it held the same keys before).
  void values_invalidating(unsigned bits, std::vector<std::pair<std::string, double>>& out) const;

 private:
  std::vector<ParamSpec> specs_;
  std::vector<double> values_;
  std::size_t index_of(std::string_view key) const;
};

// The spec with this key in a family's table; throws std::out_of_range naming `family` for a key the
// table does not declare.
const ParamSpec& spec_in(const std::vector<ParamSpec>& table, std::string_view key, const char* family);

// The renderer's own parameters (renderer_params.cpp); feature sets add theirs and may change these
// defaults.
std::vector<ParamSpec> renderer_param_specs();

// Their handles (renderer_params.cpp; the scene.* placement ones are in core/placement.h).
namespace param {
extern const FloatParam light_azimuth;
extern const FloatParam light_elevation;
extern const FloatParam light_size;
extern const ChoiceParam shadow_map_size;
extern const ChoiceParam shadow_depth_format;
extern const FloatParam shadow_bias;
extern const FloatParam shadow_slope_bias;
extern const ChoiceParam shadow_cull;
extern const BoolParam shadow_cull_casters;
extern const FloatParam view_ambient;
extern const BoolParam view_debug_quad;
extern const ChoiceParam view_debug_channel;
extern const FloatParam view_debug_quad_size;
extern const BoolParam view_light_volume;
extern const BoolParam view_flat_normals;
extern const BoolParam view_normals;
extern const BoolParam view_volumes;
extern const BoolParam scene_ground;
extern const BoolParam scene_blend_casts;
}  // namespace param

}  // namespace shadowlab
