#include "renderer/shadow_test.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab {

const std::vector<ShadowTest>& shadow_tests() {
  static const std::vector<ShadowTest> tests = [] {
    std::vector<ShadowTest> all = folder_shadow_tests();
    std::sort(all.begin(), all.end(), [](const ShadowTest& a, const ShadowTest& b) { return a.name < b.name; });
    for (std::size_t i = 1; i < all.size(); ++i)
      if (all[i].name == all[i - 1].name) throw std::logic_error("two shadow tests are called " + all[i].name);
    return all;
  }();
  return tests;
}

const ShadowTest& find_shadow_test(std::string_view name) {
  std::string names;
  for (const ShadowTest& test : shadow_tests()) {
    if (test.name == name) return test;
    names += (names.empty() ? "" : ", ") + test.name;
  }
  throw std::invalid_argument("no shadow test '" + std::string(name) + "'; the tests: " + names);
}

}  // namespace shadowlab
