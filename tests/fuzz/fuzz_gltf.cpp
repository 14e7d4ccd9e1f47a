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

// One object owns the folder: it is made before main and removed at exit. (A function-local static
// path with a separate remover object was destroyed before the remover ran, which ASan reported as a
// heap-use-after-free at exit, with an empty "crash" input: the CI fuzz stage of 8815cec.)
class WorkDir {
 public:
  WorkDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "shadowlab-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) {
      std::perror("fuzz_gltf: mkdtemp");
      std::abort();
    }
    dir_ = pattern;
  }
  ~WorkDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

const WorkDir work_dir;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::filesystem::path file = work_dir.path() / (glb ? "model.glb" : "model.gltf");
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
