// Grading a lab headless: render with the lab's exercise or solution, measure against the oracle, and
// compare each metric with its threshold. The same code runs from `shadowlab check` and the app's
// Check button.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "labs/lab.h"
#include "renderer/metrics.h"
#include "renderer/oracle.h"
#include "renderer/renderer.h"

namespace shadowlab {

// One graded quantity: passes when `value <= limit` (or >= for kAtLeast).
struct Criterion {
  enum Direction { kAtMost, kAtLeast };
  std::string metric;
  double value = 0.0;
  Direction direction = kAtMost;
  double limit = 0.0;
  std::string why;  // where the limit comes from, shown beside it
  bool passed() const { return direction == kAtMost ? value <= limit : value >= limit; }
};

struct CheckResult {
  int lab = 0;
  std::string slug;
  Impl impl = Impl::Solution;
  std::vector<Criterion> criteria;
  nlohmann::json metrics = nlohmann::json::object();  // everything measured, graded or not
  nlohmann::json parameters = nlohmann::json::object();  // the lab's parameters as graded (defaults + --set)
  std::vector<std::string> images;                   // files written under --out
  std::string error;                                 // a shader or setup failure fails the check
  double seconds = 0.0;

  bool passed() const;
  nlohmann::json to_json() const;  // {"lab","slug","impl","passed","metrics","thresholds"}
};

// What a lab's check gets: a renderer in a headless context, the scene, and the oracle for it.
class CheckContext {
 public:
  CheckContext(Renderer& renderer, const Lab& lab, Impl impl, const Scene& default_scene, std::filesystem::path out_dir);

  Renderer& renderer;
  const Lab& lab;
  Impl impl;
  std::filesystem::path out_dir;  // empty: write no images
  // A student's submission (a folder laid out like the project) whose exercise files are graded;
  // empty: the exercise in the grader's own tree.
  std::filesystem::path submission;

  // The scene to grade on (--scene, or the lab's own choice of built-in scene).
  const Scene& scene() const { return *scene_; }
  void use_scene(const Scene& scene);
  const Oracle& oracle();
  // The lab's parameters with the command line's --set values applied.
  ParamSet params() const;
  std::vector<std::string> assignments;

  struct Measurement {
    Metrics metrics;
    Truth truth;
    std::vector<float> visibility;
    double render_ms = 0.0;
    double oracle_ms = 0.0;
  };
  // Renders the current scene with these parameters and hooks, grades it against the oracle and, when
  // out_dir is set, writes `<name>_final.png` and `<name>_diff.png`.
  // The camera frames `view` (default: the whole scene's bounds).
  // A spot light lights only its cone: pixels outside it (and within kSpotConeMarginDeg of its rim, where
  // the shader's and this test's rounding may differ) are not graded. `camera` replaces the framing.
  Measurement measure(const ParamSet& params, const LabHooks& hooks, const std::string& name,
                      const Bounds* view = nullptr, const BandSpec& band = {}, int width = 960, int height = 540,
                      const OrbitCamera* camera = nullptr);

  std::vector<std::string> images;

 private:
  const Scene* scene_;
  const Scene* uploaded_ = nullptr;  // the scene the renderer holds now
  std::unique_ptr<Scene> owned_scene_;
  std::unique_ptr<Oracle> oracle_;
};

// The oracle's view of the renderer's light for the last frame: directional, or positional (spot and
// point lights) with the angle one shadow-map texel spans for the edge band.
OracleLight oracle_light(const Renderer& renderer);

inline constexpr float kSpotConeMarginDeg = 1.0f;

// The share of graded interior (non-edge) pixels whose lit/shadowed answer agrees with the oracle.
double interior_agreement(const Metrics& m);

// An orbit camera at `eye` looking at `target` (for views from a chosen place, e.g. inside a volume).
OrbitCamera camera_looking_at(const glm::vec3& eye, const glm::vec3& target, float near_plane, float far_plane);

}  // namespace shadowlab
