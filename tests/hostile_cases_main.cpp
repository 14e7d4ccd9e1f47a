// Writes the hostile models of issue 18 into a folder and lists them, one per line:
// name<TAB>file<TAB>what the refusal must mention. Used by tests/cli.sh (hostile_models).
#include <cstdio>
#include <exception>

#include "tests/hostile_cases.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: hostile_cases DIR\n");
    return 2;
  }
  try {
    for (const auto& c : shadowlab::test::write_hostile_cases(argv[1]))
      std::printf("%s\t%s\t%s\n", c.name.c_str(), c.file.c_str(), c.must_mention.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hostile_cases: %s\n", e.what());
    return 1;
  }
  return 0;
}
