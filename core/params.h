// Parameters, declared once: key, label, default, range, tooltip and what a change invalidates. The
// same declaration drives every front end (a slider, a `key=value` assignment, presets, JSON) and the
// renderer's decisions of what to redo (see Invalidates).
#pragma once

#include <optional>
#include <string>
#include <string_view>
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
  // The value when the set declares the key, else `fallback` (one lookup).
  double get_or(std::string_view key, double fallback) const;
  float get_float(std::string_view key) const { return static_cast<float>(get(key)); }
  int get_int(std::string_view key) const { return static_cast<int>(get(key)); }
  bool get_bool(std::string_view key) const { return get(key) != 0.0; }
  const std::string& get_choice(std::string_view key) const;

  // Sets a value, clamped to nothing: out of range is an error. Returns the invalidation bits of the
  // change (0 when the value did not change). Throws std::invalid_argument with a one-line message.
  unsigned set(const std::string& key, double value);
  // Parses "value" for the key's kind (numbers, true/false/on/off/1/0, a choice's name).
  unsigned set_from_string(const std::string& key, const std::string& text);
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

// A family's table of specs (the technique's, vsm's, csm's: built once, so that a frame allocates
// nothing) read by key: the spec, the set's value or the declared default when the set lacks the key,
// and a choice's name likewise. `family` names the table in the error for a key it does not declare.
const ParamSpec& spec_in(const std::vector<ParamSpec>& table, std::string_view key, const char* family);
double param_or_default(const ParamSet& params, const std::vector<ParamSpec>& table, std::string_view key,
                        const char* family);
const std::string& choice_or_default(const ParamSet& params, const std::vector<ParamSpec>& table, std::string_view key,
                                     const char* family);

// The renderer's own parameters (renderer_params.cpp); feature sets add theirs and may change these
// defaults.
std::vector<ParamSpec> renderer_param_specs();

}  // namespace shadowlab
