// Shader programs from files in shaders/ and labs/, with `#include "file"` and injected `#define`s.
//
// Every file that goes into a stage is numbered (GLSL's source-string number in `#line`), so a compile
// error is reported as "file:line: message" with the offending line quoted. ReloadableProgram watches
// those files: a saved edit is compiled into a new program that replaces the old one only if it links,
// so a broken edit never stops a running lab.
#pragma once

#include <filesystem>
#include <map>
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

struct ProgramDesc {
  std::filesystem::path vertex;    // relative to data_dir() or absolute
  std::filesystem::path geometry;  // optional
  std::filesystem::path fragment;
  std::vector<std::pair<std::string, std::string>> defines;
  // Virtual include names: `#include "lab/shadow.glsl"` can be pointed at a lab's exercise or solution.
  std::map<std::string, std::filesystem::path> includes;
};

struct ProgramBuild {
  GlProgram program;  // empty on failure
  std::string error;  // "file:line: message" lines with the quoted source line
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
  int generation() const { return generation_; }       // bumps on every successful swap
  const ProgramDesc& desc() const { return desc_; }

 private:
  ProgramDesc desc_;
  GlProgram program_;
  std::string error_;
  int generation_ = 0;
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> watched_;
};

// A uniform location resolved once per program generation, with typed setters.
class Uniform {
 public:
  Uniform() = default;
  Uniform(GLuint program, const char* name) : location_(glGetUniformLocation(program, name)) {}
  void set(float v) const { glUniform1f(location_, v); }
  void set(int v) const { glUniform1i(location_, v); }
  void set(const glm::vec2& v) const { glUniform2f(location_, v.x, v.y); }
  void set(const glm::vec3& v) const { glUniform3f(location_, v.x, v.y, v.z); }
  void set(const glm::vec4& v) const { glUniform4f(location_, v.x, v.y, v.z, v.w); }
  void set(const glm::mat4& m) const { glUniformMatrix4fv(location_, 1, GL_FALSE, &m[0][0]); }
  bool present() const { return location_ >= 0; }

 private:
  GLint location_ = -1;
};

}  // namespace shadowlab
