// Shader programs from files in shaders/ and labs/, with `#include "file"` and injected `#define`s.
//
// Every file that goes into a stage gets its own range of line numbers (`#line`): file k's line n is
// line k * kShaderLineStride + n of the stage. Drivers report errors by line, and not all of them keep
// the source-string number of `#line` (Mesa reports semantic errors against string 0), so the line alone
// tells which file and line an error is in: "file:line:col: error: message" with the line quoted.
// ReloadableProgram watches those files: a saved edit is compiled into a new program that replaces the
// old one only if it links, so a broken edit never stops a running lab.
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl_objects.h"

namespace shadowlab {

// Folder holding shaders/ and labs/ (the source tree by default; SHADOWLAB_DATA_DIR overrides it).
std::filesystem::path data_dir();
// A path relative to data_dir() when it is inside it, for messages.
std::string display_path(const std::filesystem::path& path);

// Who may include what. A confined file (a student's exercise, or a file from a submission) may include
// only the virtual names its lab offers; any other name, an absolute path or a path leaving the data
// folder is refused before anything is read. Other files include freely.
struct IncludeRules {
  std::set<std::filesystem::path> confined;  // as given in ProgramDesc::includes (resolved before comparing)
  std::set<std::string> offered;             // e.g. "lab/bias.glsl"
  // How messages name a file (resolved before comparing): a lab's slot file as the exercise file the
  // student knows ("labs/00_basic_shadow_map/exercise.glsl"), wherever the copy being built sits (a
  // submission's folder, a temporary one), so that no message shows the grading machine's paths.
  // Files not named here are shown relative to data_dir() (display_path).
  std::map<std::filesystem::path, std::string> shown_as = {};
};

// One compiler message, placed in the file and line it is about.
struct ShaderDiagnostic {
  std::filesystem::path file;  // empty when the driver's line could not be placed
  std::string shown;           // how messages name `file` (IncludeRules::shown_as); empty: display_path(file)
  int line = 0;                // 1-based; 0 unknown
  int column = 0;              // 1-based, as g++ counts (Mesa's 0-based column plus 1); 0 when the driver gives none
  bool error = true;           // false: a warning
  std::string message;         // the driver's text after its location and severity
  // "file:line:col: error: message" (col omitted when unknown) and, when the file can be read, the
  // line quoted below it.
  std::string to_string() const;
};

// Lines of a stage per file: a file longer than this is refused (no shader file comes near it).
inline constexpr int kShaderLineStride = 100000;

// Places a driver's info log: understands Mesa's "0:12(5): error: ...", NVIDIA's "0(12) : error C0000:
// ..." and the "ERROR: 0:12: ..." of AMD, Intel, Apple and glslang. `files` is the stage's file table
// (preprocess_shader's). Lines it cannot parse are kept as diagnostics without a file.
std::vector<ShaderDiagnostic> parse_shader_log(const std::string& log, const std::vector<std::filesystem::path>& files);

struct ProgramDesc {
  std::filesystem::path vertex;    // relative to data_dir() or absolute
  std::filesystem::path geometry;  // optional
  std::filesystem::path fragment;
  std::vector<std::pair<std::string, std::string>> defines;
  // Virtual include names: `#include "lab/shadow.glsl"` can be pointed at a lab's exercise or solution.
  std::map<std::string, std::filesystem::path> includes;
  IncludeRules rules = {};
  // Outputs of the last vertex-processing stage that transform feedback may capture (interleaved).
  std::vector<std::string> feedback_varyings = {};
  // Uniforms compiled as constants (name, value): a line declaring one of them alone, `uniform T name;`
  // with T int, uint, bool or float, becomes `const T name = T(value);` in every file of the stage (a
  // student's too), so the compiler unrolls the loops and drops the branches the value decides. The
  // line keeps its number and any comment after it; a name declared any other way stays a uniform.
  std::vector<std::pair<std::string, std::string>> constants = {};
};

// `line` with a declaration of one of `constants` made a constant (see ProgramDesc::constants); empty
// when the line declares none of them. Exposed for tests.
std::string uniform_as_constant(const std::string& line, const std::vector<std::pair<std::string, std::string>>& constants);

struct ProgramBuild {
  GlProgram program;  // empty on failure
  std::string error;  // "file:line:col: error: message" lines with the quoted source line
  std::string warnings;  // the same for warnings, also when the build succeeded
  std::vector<ShaderDiagnostic> diagnostics;
  std::vector<std::filesystem::path> files;  // every file read, for live reload
};

ProgramBuild build_program(const ProgramDesc& desc);

// Expands includes and injects defines; exposed for tests. `files` receives the source-string table.
std::string preprocess_shader(const std::filesystem::path& path, const ProgramDesc& desc,
                              std::vector<std::filesystem::path>& files, std::string& error);

class ReloadableProgram {
 public:
  ReloadableProgram() = default;
  explicit ReloadableProgram(ProgramDesc desc);

  // Builds now; returns false (keeping any previous program) if it fails.
  bool rebuild();
  // Rebuilds when a source file changed on disk. Returns true when a new program was swapped in.
  bool poll_files();
  void set_desc(ProgramDesc desc);

  GLuint id() const { return program_.id(); }
  bool valid() const { return static_cast<bool>(program_); }
  const std::string& error() const { return error_; }  // last failure, empty after a success
  const std::string& warnings() const { return warnings_; }  // the last build's warnings
  int generation() const { return generation_; }       // bumps on every successful swap
  const ProgramDesc& desc() const { return desc_; }

 private:
  ProgramDesc desc_;
  GlProgram program_;
  std::string error_;
  std::string warnings_;
  int generation_ = 0;
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> watched_;
};

// A uniform location resolved once per program generation, with typed setters.
class Uniform {
 public:
  Uniform() = default;
  Uniform(GLuint program, const char* name) : location_(glGetUniformLocation(program, name)) {
    lookups_.fetch_add(1, std::memory_order_relaxed);
  }
  explicit Uniform(GLint location) : location_(location) {}
  void set(float v) const { glUniform1f(location_, v); }
  void set(int v) const { glUniform1i(location_, v); }
  void set(const glm::vec2& v) const { glUniform2f(location_, v.x, v.y); }
  void set(const glm::vec3& v) const { glUniform3f(location_, v.x, v.y, v.z); }
  void set(const glm::vec4& v) const { glUniform4f(location_, v.x, v.y, v.z, v.w); }
  void set(const glm::mat4& m) const { glUniformMatrix4fv(location_, 1, GL_FALSE, &m[0][0]); }
  // An array of `count` vec3 (the uniform looked up by the array's name or its element 0).
  void set(const glm::vec3* v, int count) const { glUniform3fv(location_, count, &v->x); }
  bool present() const { return location_ >= 0; }
  // Locations looked up by name so far, by every thread (glGetUniformLocation calls made here): tests
  // count them per frame.
  static long lookups() { return lookups_.load(std::memory_order_relaxed); }

 private:
  GLint location_ = -1;
  static inline std::atomic<long> lookups_{0};
};

// The uniform locations of one ReloadableProgram, looked up again only when the program was swapped
// (its generation changed: a live reload's new program may place its uniforms elsewhere). `Locations`
// is a struct of Uniform members; `lookup(GLuint program)` returns it filled. Usage:
//   struct ViewUniforms { Uniform view_proj, size; };
//   UniformCache<ViewUniforms> view_u_;
//   const ViewUniforms& u = view_u_.get(view_, [](GLuint id) { return ViewUniforms{{id, "u_view_proj"}, {id, "u_size"}}; });
template <class Locations>
class UniformCache {
 public:
  template <class Lookup>
  const Locations& get(const ReloadableProgram& program, Lookup&& lookup) {
    if (generation_ != program.generation()) {
      locations_ = lookup(program.id());
      generation_ = program.generation();
    }
    return locations_;
  }

 private:
  int generation_ = -1;  // a program's generation is never negative: the first get looks up
  Locations locations_{};
};

}  // namespace shadowlab
