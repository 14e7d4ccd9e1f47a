// libFuzzer target for the glTF loader: any bytes must give a Scene or a LoadError, never a crash, a
// hang, a leak, undefined behaviour or any other exception. Built with clang only (scripts/fuzz).
//
// load_gltf takes a path (it resolves external buffers against the model's folder), so each input is
// written to a private temporary folder, as model.glb when it starts with the GLB magic and as
// model.gltf otherwise. Nothing else is in that folder: an input naming an external buffer finds none.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/gltf_loader.h"

namespace {

const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "shadowlab-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) {
      std::perror("fuzz_gltf: mkdtemp");
      std::abort();
    }
    return std::filesystem::path(pattern);
  }();
  return dir;
}

struct RemoveWorkDir {
  ~RemoveWorkDir() {
    std::error_code ec;
    std::filesystem::remove_all(work_dir(), ec);
  }
} remove_at_exit;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::filesystem::path file = work_dir() / (glb ? "model.glb" : "model.gltf");
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    const shadowlab::Scene scene = shadowlab::load_gltf(file);
    (void)scene.triangle_count();
  } catch (const shadowlab::LoadError&) {
    // The expected outcome for nearly every input: a clear refusal.
  }
  std::filesystem::remove(file);
  return 0;
}
