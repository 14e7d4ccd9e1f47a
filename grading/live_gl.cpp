// Lab 0's GL exercise in the window (grading/live_cpp.h): the student's gl_shadow_target.cpp built into a
// shared library and loaded into the window's process, whose renderer then calls its two functions
// (renderer/shadow_target.h, ShadowTargetCode). On the student's own machine only: grading runs the same
// file in the sandbox instead (labs/00_basic_shadow_map/lab.cpp).
#include "grading/live_gl.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/untrusted.h"
#include "grading/cpp_exercise.h"
#include "grading/platform_process.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kEntry = "shadowlab_live_shadow_target_code";

// Built with the student's file: hands out the two functions it defines (linked with -Bsymbolic, so the
// library's own, never the window's).
constexpr const char* kShim =
    "#include \"renderer/shadow_target.h\"\n"
    "extern \"C\" __attribute__((visibility(\"default\"))) void shadowlab_live_shadow_target_code(\n"
    "    shadowlab::ShadowTargetCode* out) {\n"
    "  out->create = &shadowlab::create_shadow_target;\n"
    "  out->begin = &shadowlab::begin_shadow_pass;\n"
    "}\n";

void write_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(file.string() + ": cannot be written");
}

std::string read_log(const fs::path& log, const fs::path& dir) {
  std::ifstream in(log, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  // The copy's folder out of every path: the compiler's words name the file as the student knows it.
  const std::string prefix = (dir / "").string();
  for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
  return printable(text, 4000);
}

}  // namespace

bool live_gl_exercise_supported(const std::string& file) {
  return fs::path(file).filename() == "gl_shadow_target.cpp";
}

ShadowTargetCode build_live_gl_exercise(const fs::path& dir, const std::string& file, const std::string& text) {
  // The student's text at its place in the project, inside `dir`: its includes of the lab's headers are
  // found in the data folder (-iquote), and the messages name labs/NN_lab/gl_*.cpp.
  write_file(dir / file, text);
  write_file(dir / "live_shim.cpp", kShim);
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
    const std::string words = read_log(log, dir);
    throw std::runtime_error(file + " does not build:\n" +
                             (words.empty() ? built.error + built.signal_name : words));
  }
  std::string error;
  void* entry = platform::load_library_symbol(library, kEntry, error);
  if (!entry) throw std::runtime_error(file + ": its library cannot be loaded: " + error);
  ShadowTargetCode code;
  reinterpret_cast<void (*)(ShadowTargetCode*)>(entry)(&code);
  return code;
}

}  // namespace shadowlab
