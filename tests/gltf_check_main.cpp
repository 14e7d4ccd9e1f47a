// Loads each glTF file named on the command line and prints the loader's verdict, one line per file:
// file<TAB>loaded|refused<TAB>the refusal (or the triangle count). Used by tests/validator/crosscheck.sh.
#include <cstdio>
#include <string>

#include "core/gltf_loader.h"

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    try {
      const shadowlab::Scene scene = shadowlab::load_gltf(argv[i]);
      std::printf("%s\tloaded\t%zu triangles\n", argv[i], scene.triangle_count());
    } catch (const shadowlab::LoadError& e) {
      std::printf("%s\trefused\t%s\n", argv[i], e.what());
    }
  }
  return 0;
}
