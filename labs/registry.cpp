#include "labs/registry.h"

#include <utility>

namespace shadowlab {

Lab folder_lab(Lab lab, int number, std::string slug) {
  lab.number = number;
  lab.slug = std::move(slug);
  const std::string prefix = lab.folder() + "/";
  for (const auto& [file, text] : compiled_exercises())
    if (file.starts_with(prefix)) lab.compiled_copies.emplace(file, text);
  return lab;
}

const std::vector<Lab>& all_labs() {
  static const std::vector<Lab> labs = folder_labs();
  return labs;
}

const Lab* find_lab(int number) {
  for (const auto& lab : all_labs())
    if (lab.number == number) return &lab;
  return nullptr;
}

const Lab* find_lab_named(std::string_view slug) {
  for (const auto& lab : all_labs())
    if (lab.slug == slug) return &lab;
  return nullptr;
}

const Lab* find_lab_offering(std::string_view bench_technique) {
  for (const auto& lab : all_labs())
    for (const auto& technique : lab.bench)
      if (technique.name == bench_technique) return &lab;
  return nullptr;
}

}  // namespace shadowlab
