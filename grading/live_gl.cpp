// The labs' GL exercises in the window (grading/live_cpp.h): the student's gl_*.cpp built into a shared
// library and loaded into the window's process, whose renderer then calls its functions
// (renderer/gl_host_code.h). On the student's own machine only: grading runs the same file in the
// sandbox instead (the labs' checks, grading/gl_exercise_check.h).
#include "grading/live_gl.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/untrusted.h"
#include "grading/cpp_exercise.h"
#include "grading/platform_process.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kEntry = "shadowlab_live_gl_code";

// What each GL exercise file defines, and where the window's renderer takes it (GlHostCode's fields).
struct LiveFile {
  const char* name;     // the file's name in its lab folder
  const char* header;   // the renderer's header that declares its functions
  std::vector<const char*> functions;  // in the order the library hands them out
  void (*take)(GlHostCode& code, void* const* functions);
};

template <typename F>
F as(void* p) {
  return reinterpret_cast<F>(p);
}

const std::vector<LiveFile>& live_files() {
  static const std::vector<LiveFile> files = {
      {"gl_shadow_target.cpp", "renderer/shadow_target.h", {"create_shadow_target", "begin_shadow_pass"},
       [](GlHostCode& c, void* const* f) {
         c.create_shadow_target = as<decltype(c.create_shadow_target)>(f[0]);
         c.begin_shadow_pass = as<decltype(c.begin_shadow_pass)>(f[1]);
       }},
      {"gl_moments_target.cpp", "renderer/moments_target.h", {"create_moments_target", "begin_moments_pass"},
       [](GlHostCode& c, void* const* f) {
         c.create_moments_target = as<decltype(c.create_moments_target)>(f[0]);
         c.begin_moments_pass = as<decltype(c.begin_moments_pass)>(f[1]);
       }},
      {"gl_blur_passes.cpp", "renderer/blur_passes.h", {"create_blur_target", "run_blur_passes"},
       [](GlHostCode& c, void* const* f) {
         c.create_blur_target = as<decltype(c.create_blur_target)>(f[0]);
         c.run_blur_passes = as<decltype(c.run_blur_passes)>(f[1]);
       }},
      {"gl_volume_stencil.cpp", "renderer/volume_stencil.h", {"stencil_pass", "begin_additive_lit_pass"},
       [](GlHostCode& c, void* const* f) {
         c.stencil_pass = as<decltype(c.stencil_pass)>(f[0]);
         c.begin_additive_lit_pass = as<decltype(c.begin_additive_lit_pass)>(f[1]);
       }},
  };
  return files;
}

const LiveFile* live_file(const std::string& file) {
  const std::string name = fs::path(file).filename().string();
  for (const LiveFile& f : live_files())
    if (name == f.name) return &f;
  return nullptr;
}

// Built with the student's file: hands out the functions it defines (linked with -Bsymbolic, so the
// library's own, never the window's), and nothing else of ours (-z defs: a function left out is named).
std::string shim(const LiveFile& f) {
  std::string text = std::string("#include \"") + f.header + "\"\nextern \"C\" __attribute__((visibility(\"default\"))) void " +
                     kEntry + "(void** out) {\n";
  for (std::size_t i = 0; i < f.functions.size(); ++i)
    text += "  out[" + std::to_string(i) + "] = reinterpret_cast<void*>(&shadowlab::" + f.functions[i] + ");\n";
  return text + "}\n";
}

void write_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(file.string() + ": cannot be written");
}

}  // namespace

bool live_gl_exercise_supported(const std::string& file) { return live_file(file) != nullptr; }

GlHostCode build_live_gl_exercise(const fs::path& dir, const std::string& file, const std::string& text, GlHostCode code) {
  const LiveFile* live = live_file(file);
  if (!live) throw std::runtime_error(file + ": the window runs no such GL exercise");
  // The student's text at its place in the project, inside `dir`: its includes of the lab's headers are
  // found in the data folder (-iquote), and the messages name labs/NN_lab/gl_*.cpp.
  write_file(dir / file, text);
  write_file(dir / "live_shim.cpp", shim(*live));
  const fs::path library = dir / "libexercise.so";
  std::vector<std::string> argv = exercise_compiler_command();
  for (const char* a : {"-fno-diagnostics-color", "-fmax-errors=10", "-fPIC", "-shared", "-Wl,-Bsymbolic",
                        "-Wl,-z,defs", "-iquote"})
    argv.push_back(a);
  argv.push_back(data_dir().string());
  for (const fs::path& f : {dir / file, dir / "live_shim.cpp", fs::path("-o"), library}) argv.push_back(f.string());
  argv.push_back("-lepoxy");
  platform::ChildLimits limits;
  limits.wall_seconds = 120.0;
  const fs::path log = dir / "build.log";
  const platform::ChildOutcome built = platform::run_child(argv, limits, log);
  if (built.kind != platform::ChildOutcome::Kind::Exited || built.exit_code != 0) {
    // The compiler's words naming the file as the student knows it (our folders out of every path).
    std::ifstream in(log, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const std::string words = printable(compiler_words(text.str(), dir / file, file, dir), 4000);
    throw std::runtime_error(file + " does not build:\n" +
                             (words.empty() ? built.error + built.signal_name : words));
  }
  std::string error;
  void* entry = platform::load_library_symbol(library, kEntry, error);
  if (!entry) throw std::runtime_error(file + ": its library cannot be loaded: " + error);
  std::vector<void*> functions(live->functions.size(), nullptr);
  reinterpret_cast<void (*)(void**)>(entry)(functions.data());
  live->take(code, functions.data());
  return code;
}

}  // namespace shadowlab
