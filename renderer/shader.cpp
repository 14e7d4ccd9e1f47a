#include "renderer/shader.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace shadowlab {

namespace fs = std::filesystem;

fs::path data_dir() {
  if (const char* env = std::getenv("SHADOWLAB_DATA_DIR"); env && *env) return fs::path(env);
  return fs::path(SHADOWLAB_DATA_DIR);
}

std::string display_path(const fs::path& path) {
  std::error_code ec;
  const fs::path rel = fs::relative(path, data_dir(), ec);
  if (!ec && !rel.empty() && *rel.begin() != "..") return rel.generic_string();
  return path.generic_string();
}

namespace {

fs::path resolve(const fs::path& p) { return p.is_absolute() ? p : data_dir() / p; }

bool read_text(const fs::path& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

struct Expander {
  const ProgramDesc& desc;
  std::vector<fs::path>& files;
  std::string& error;
  std::set<fs::path> included;  // include-once, so shared helpers can be included from several files

  // Appends the expanded text of `path` to `out`; returns false on error.
  bool expand(const fs::path& path, std::ostringstream& out, bool top, int depth) {
    if (depth > 16) {
      error = display_path(path) + ": includes nested more than 16 deep (an include cycle?)";
      return false;
    }
    std::string text;
    if (!read_text(path, text)) {
      error = display_path(path) + ": cannot read shader file";
      return false;
    }
    const int index = static_cast<int>(files.size());
    files.push_back(path);
    static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    static const std::regex version_re(R"(^\s*#\s*version\b.*$)");
    const auto lines = split_lines(text);
    if (!top) out << "#line 1 " << index << '\n';
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      const int line_no = static_cast<int>(i) + 1;
      std::smatch m;
      if (std::regex_match(line, version_re)) {
        if (!top) continue;  // only the stage's own file declares the version
        out << line << '\n';
        for (const auto& [name, value] : desc.defines) out << "#define " << name << ' ' << value << '\n';
        out << "#line " << line_no + 1 << ' ' << index << '\n';
        continue;
      }
      if (std::regex_match(line, m, include_re)) {
        const std::string name = m[1];
        fs::path target;
        if (auto it = desc.includes.find(name); it != desc.includes.end()) {
          target = resolve(it->second);
        } else if (fs::exists(path.parent_path() / name)) {
          target = path.parent_path() / name;
        } else {
          target = data_dir() / "shaders" / name;
        }
        if (!fs::exists(target)) {
          error = display_path(path) + ":" + std::to_string(line_no) + ": cannot find include \"" + name + "\"\n    " +
                  std::to_string(line_no) + " | " + line;
          return false;
        }
        const fs::path canonical = fs::weakly_canonical(target);
        if (included.insert(canonical).second) {
          if (!expand(canonical, out, false, depth + 1)) return false;
        }
        out << "#line " << line_no + 1 << ' ' << index << '\n';
        continue;
      }
      out << line << '\n';
    }
    return true;
  }
};

// Rewrites the driver's "S:L(C): message" lines as "file:L:C: message" and quotes the source line.
std::string explain_log(const std::string& log, const std::vector<fs::path>& files) {
  static const std::regex mesa_re(R"(^(\d+):(\d+)\((\d+)\): (.*)$)");
  std::ostringstream out;
  for (const auto& line : split_lines(log)) {
    std::smatch m;
    if (!std::regex_match(line, m, mesa_re)) {
      if (!line.empty()) out << line << '\n';
      continue;
    }
    const auto index = static_cast<std::size_t>(std::stoul(m[1]));
    const int line_no = std::stoi(m[2]);
    if (index >= files.size()) {
      out << line << '\n';
      continue;
    }
    out << display_path(files[index]) << ':' << line_no << ':' << m[3] << ": " << m[4] << '\n';
    std::string text;
    if (read_text(files[index], text)) {
      const auto source_lines = split_lines(text);
      if (line_no >= 1 && static_cast<std::size_t>(line_no) <= source_lines.size()) {
        out << "    " << line_no << " | " << source_lines[static_cast<std::size_t>(line_no) - 1] << '\n';
      }
    }
  }
  return out.str();
}

// Shaders and programs report status and logs through parallel entry points; these take either pair.
template <typename GetIv>
bool succeeded(GLuint id, GLenum status, GetIv get_iv) {
  GLint ok = GL_FALSE;
  get_iv(id, status, &ok);
  return ok == GL_TRUE;
}

template <typename GetIv, typename GetLog>
std::string info_log(GLuint id, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(id, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  get_log(id, length, nullptr, log.data());
  return log.c_str();  // up to the terminating NUL
}

GlShader compile_stage(GLenum type, const fs::path& path, const ProgramDesc& desc, std::vector<fs::path>& all_files,
                       std::string& error) {
  std::vector<fs::path> files;
  const std::string source = preprocess_shader(resolve(path), desc, files, error);
  all_files.insert(all_files.end(), files.begin(), files.end());
  if (!error.empty()) return {};
  GlShader shader = make_shader(type);
  const char* text = source.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  if (!succeeded(shader.id(), GL_COMPILE_STATUS, glGetShaderiv)) {
    error = explain_log(info_log(shader.id(), glGetShaderiv, glGetShaderInfoLog), files);
    if (error.empty()) error = display_path(resolve(path)) + ": compile failed with no log";
    return {};
  }
  return shader;
}

}  // namespace

std::string preprocess_shader(const fs::path& path, const ProgramDesc& desc, std::vector<fs::path>& files,
                              std::string& error) {
  Expander expander{desc, files, error, {}};
  std::ostringstream out;
  expander.included.insert(fs::weakly_canonical(path));
  if (!expander.expand(path, out, true, 0)) return {};
  return out.str();
}

ProgramBuild build_program(const ProgramDesc& desc) {
  ProgramBuild result;
  struct Stage {
    GLenum type;
    const fs::path& path;
  };
  const Stage stages[] = {{GL_VERTEX_SHADER, desc.vertex}, {GL_GEOMETRY_SHADER, desc.geometry},
                          {GL_FRAGMENT_SHADER, desc.fragment}};
  std::vector<GlShader> shaders;
  for (const auto& stage : stages) {
    if (stage.path.empty()) continue;
    GlShader shader = compile_stage(stage.type, stage.path, desc, result.files, result.error);
    if (!shader) return result;
    shaders.push_back(std::move(shader));
  }
  GlProgram program = GlProgram::create();
  for (const auto& s : shaders) glAttachShader(program.id(), s.id());
  glLinkProgram(program.id());
  for (const auto& s : shaders) glDetachShader(program.id(), s.id());
  if (!succeeded(program.id(), GL_LINK_STATUS, glGetProgramiv)) {
    result.error = display_path(resolve(desc.fragment)) + ": link failed: " +
                   info_log(program.id(), glGetProgramiv, glGetProgramInfoLog);
    return result;
  }
  result.program = std::move(program);
  return result;
}

ReloadableProgram::ReloadableProgram(ProgramDesc desc) : desc_(std::move(desc)) {}

void ReloadableProgram::set_desc(ProgramDesc desc) {
  desc_ = std::move(desc);
  watched_.clear();  // forces a rebuild on the next poll
}

bool ReloadableProgram::rebuild() {
  ProgramBuild build = build_program(desc_);
  watched_.clear();
  for (const auto& f : build.files) {
    std::error_code ec;
    watched_.emplace_back(f, fs::last_write_time(f, ec));
  }
  if (!build.program) {
    error_ = build.error;
    return false;
  }
  program_ = std::move(build.program);
  error_.clear();
  ++generation_;
  return true;
}

bool ReloadableProgram::poll_files() {
  bool changed = watched_.empty();
  for (const auto& [path, time] : watched_) {
    std::error_code ec;
    if (fs::last_write_time(path, ec) != time) changed = true;
  }
  return changed && rebuild();
}

}  // namespace shadowlab
