// Grading on a scene that is not the lab's own (check --scene): the scene is moved and scaled into the lab's
// frame (grading/check.h, LabFrame), and what the lab's solution itself fails there is graded against the
// solution's own value (grade_against_solution).
#include <map>
#include <string>

#include "grading/check.h"

namespace shadowlab {

LabFrame lab_frame(const Bounds& scene, const Bounds& lab) {
  LabFrame f;
  if (scene.empty() || lab.empty()) return f;
  // In double: a scene 1e6 units from the origin keeps the small differences of its box.
  f.from = 0.5 * (glm::dvec3(scene.min) + glm::dvec3(scene.max));
  f.to = 0.5 * (glm::dvec3(lab.min) + glm::dvec3(lab.max));
  const double radius = 0.5 * glm::length(glm::dvec3(scene.max) - glm::dvec3(scene.min));
  const double lab_radius = 0.5 * glm::length(glm::dvec3(lab.max) - glm::dvec3(lab.min));
  if (radius > 0.0) f.scale = lab_radius / radius;
  return f;
}

Scene in_lab_frame(const Scene& scene, const LabFrame& frame) {
  Scene out = scene;
  out.origin = glm::dvec3(0.0);
  for (Mesh& mesh : out.meshes)
    for (glm::vec3& p : mesh.positions) p = frame.apply(p);
  return out;
}

void grade_against_solution(CheckResult& result, const CheckResult& solution) {
  if (!solution.error.empty()) {
    result.notes.push_back("the lab's solution could not be graded on this scene (" + solution.error +
                           "): the lab's own limits apply");
    return;
  }
  std::map<std::string, const Criterion*> theirs;
  int measurable = 0, measures = 0;  // the solution's image conditions, and those it could measure
  for (const auto& c : solution.criteria) {
    theirs[c.metric] = &c;
    if (!c.metric.ends_with("graded_pixels")) continue;
    ++measures;
    measurable += c.passed() ? 1 : 0;
  }
  // No evidence at all (a scene with nothing to grade, e.g. one degenerate triangle): no check passes on it,
  // so the lab's limits stay and its graded_pixels criteria fail as not measurable.
  if (measures > 0 && measurable == 0) {
    result.notes.push_back("nothing on this scene can be graded (the solution sees no lit or shadowed pixel in any "
                           "condition): the lab's own limits apply");
    return;
  }
  int against = 0, unmeasurable = 0;
  for (auto& c : result.criteria) {
    const auto found = theirs.find(c.metric);
    if (found == theirs.end() || found->second->passed()) continue;
    const Criterion& s = *found->second;
    // Nothing to compare with: the solution grades no pixel there, or finds nothing of what the condition
    // needs (no shadowed quarter, no camera inside a volume: an at-least criterion at 0).
    if (c.metric.ends_with("graded_pixels") || (s.direction == Criterion::kAtLeast && s.value <= 0.0)) {
      c.basis = Criterion::kNotMeasurable;
      ++unmeasurable;
      continue;
    }
    c.basis = Criterion::kSolutionValue;
    c.limit = c.direction == Criterion::kAtMost ? s.value * (1.0 + kAgainstSolutionMargin)
                                                : s.value * (1.0 - kAgainstSolutionMargin);
    ++against;
  }
  if (against + unmeasurable > 0)
    result.notes.push_back("this scene is not the lab's own: " + std::to_string(against) +
                           " criteria the solution itself fails here are graded against the solution's value (" +
                           std::to_string(static_cast<int>(kAgainstSolutionMargin * 100)) + " % margin), " +
                           std::to_string(unmeasurable) + " cannot be measured here and are not graded");
}

}  // namespace shadowlab
