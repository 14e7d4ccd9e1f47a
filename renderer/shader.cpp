#include "renderer/shader.h"

#include "core/platform.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace shadowlab {

namespace fs = std::filesystem;

fs::path data_dir() {
  if (fs::path env = platform::env_path("SHADOWLAB_DATA_DIR"); !env.empty()) return env;
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

// IncludeRules::shown_as by the files' resolved, canonical paths (what the expander reads).
using ShownNames = std::map<fs::path, std::string>;
ShownNames shown_names(const IncludeRules& rules) {
  ShownNames out;
  for (const auto& [file, name] : rules.shown_as) out[fs::weakly_canonical(resolve(file))] = name;
  return out;
}

// How messages name `path`: its IncludeRules::shown_as name, else relative to the data folder.
std::string shown_name(const fs::path& path, const ShownNames& names) {
  if (auto it = names.find(fs::weakly_canonical(path)); it != names.end()) return it->second;
  return display_path(path);
}

// Shader sources may come from a student's submission: only regular files are read (a FIFO or a device
// would block or never end), and none larger than any shader could be.
constexpr std::uint64_t kMaxShaderBytes = 1u << 20;

bool read_text(const fs::path& path, std::string& out) {
  try {
    out = platform::read_regular_file(path, kMaxShaderBytes);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Include names and driver text go into messages: keep them on one line and short.
std::string printable(const std::string& text, std::size_t limit = 200) {
  std::string out;
  for (char c : text.substr(0, limit)) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  return text.size() > limit ? out + "..." : out;
}

std::string line_directive(int file_index, int line) {
  return "#line " + std::to_string(file_index * kShaderLineStride + line) + " 0\n";
}

struct Expander {
  const ProgramDesc& desc;
  std::vector<fs::path>& files;
  std::string& error;
  std::set<fs::path> included;  // include-once, so shared helpers can be included from several files
  std::set<fs::path> confined;  // desc.rules.confined, canonical
  ShownNames names;             // desc.rules.shown_as, canonical

  std::string shown(const fs::path& path) const { return shown_name(path, names); }
  // "file:line:col: error: ", the column (from 1) that of the include's name (its opening quote).
  std::string where(const fs::path& path, int line_no, const std::string& line) const {
    const std::size_t quote = line.find('"');
    const std::size_t column = quote == std::string::npos ? 1 : quote + 1;
    return shown(path) + ":" + std::to_string(line_no) + ":" + std::to_string(column) + ": error: ";
  }
  static std::string quote(int line_no, const std::string& line) {
    return "\n    " + std::to_string(line_no) + " | " + printable(line);
  }

  // Where `#include "name"` in `path` leads; empty (and `error` set) when it may not be followed.
  fs::path include_target(const fs::path& path, int line_no, const std::string& line, const std::string& name) {
    const fs::path as_path(name);
    if (as_path.is_absolute() || as_path.has_root_name() || as_path.has_root_directory()) {
      error = where(path, line_no, line) + "#include \"" + printable(name) + "\": an absolute path is not allowed" + quote(line_no, line);
      return {};
    }
    for (const auto& part : as_path)
      if (part == "..") {
        error = where(path, line_no, line) + "#include \"" + printable(name) + "\": a path may not leave its folder (..)" +
                quote(line_no, line);
        return {};
      }
    if (confined.count(fs::weakly_canonical(path))) {
      // An offered renderer file (not a "lab/" name in the map) is the renderer's, never one beside the
      // student's file: a planted copy there would not be confined.
      if (desc.rules.offered.count(name) && !desc.includes.count(name) && fs::is_regular_file(data_dir() / "shaders" / name))
        return data_dir() / "shaders" / name;
      if (!desc.rules.offered.count(name) || !desc.includes.count(name)) {
        std::string offered;
        for (const auto& o : desc.rules.offered) offered += (offered.empty() ? "" : ", ") + ("\"" + o + "\"");
        error = where(path, line_no, line) + "#include \"" + printable(name) + "\" is not offered by this lab; your file may include " +
                (offered.empty() ? std::string("nothing") : offered) + quote(line_no, line);
        return {};
      }
    }
    if (auto it = desc.includes.find(name); it != desc.includes.end()) return resolve(it->second);
    if (fs::exists(path.parent_path() / name)) return path.parent_path() / name;
    return data_dir() / "shaders" / name;
  }

  // Appends the expanded text of `path` to `out`; returns false on error.
  bool expand(const fs::path& path, std::ostringstream& out, bool top, int depth) {
    if (depth > 16) {
      error = shown(path) + ": includes nested more than 16 deep (an include cycle?)";
      return false;
    }
    std::string text;
    if (!read_text(path, text)) {
      error = shown(path) + ": cannot read shader file (missing, not a regular file, or over 1 MiB)";
      return false;
    }
    const int index = static_cast<int>(files.size());
    files.push_back(path);
    // A trailing // comment is allowed after the name, as on any other line.
    static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
    static const std::regex version_re(R"(^\s*#\s*version\b.*$)");
    const auto lines = split_lines(text);
    if (lines.size() >= static_cast<std::size_t>(kShaderLineStride)) {
      error = shown(path) + ": more than " + std::to_string(kShaderLineStride - 1) + " lines";
      return false;
    }
    if (!top) out << line_directive(index, 1);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string& line = lines[i];
      const int line_no = static_cast<int>(i) + 1;
      std::smatch m;
      if (std::regex_match(line, version_re)) {
        if (!top) continue;  // only the stage's own file declares the version
        out << line << '\n';
        for (const auto& [name, value] : desc.defines) out << "#define " << name << ' ' << value << '\n';
        out << line_directive(index, line_no + 1);
        continue;
      }
      if (std::regex_match(line, m, include_re)) {
        const std::string name = m[1];
        const fs::path target = include_target(path, line_no, line, name);
        if (target.empty()) return false;
        if (!fs::exists(target)) {
          error = where(path, line_no, line) + "cannot find include \"" + printable(name) + "\"" + quote(line_no, line);
          return false;
        }
        const fs::path canonical = fs::weakly_canonical(target);
        if (included.insert(canonical).second) {
          if (!expand(canonical, out, false, depth + 1)) return false;
        }
        out << line_directive(index, line_no + 1);
        continue;
      }
      if (!desc.constants.empty()) {
        if (std::string constant = uniform_as_constant(line, desc.constants); !constant.empty()) {
          out << constant << '\n';
          continue;
        }
      }
      out << line << '\n';
    }
    return true;
  }
};

ShaderDiagnostic place(std::size_t line, int column, bool is_error, std::string message,
                       const std::vector<fs::path>& files) {
  ShaderDiagnostic d;
  d.column = column;
  d.error = is_error;
  d.message = std::move(message);
  const std::size_t index = line / static_cast<std::size_t>(kShaderLineStride);
  if (index < files.size()) {
    d.file = files[index];
    d.line = static_cast<int>(line % static_cast<std::size_t>(kShaderLineStride));
  } else {
    d.line = static_cast<int>(line);
  }
  return d;
}

}  // namespace

std::string uniform_as_constant(const std::string& line, const std::vector<std::pair<std::string, std::string>>& constants) {
  if (line.find("uniform") == std::string::npos) return {};
  static const std::regex uniform_re(R"(^(\s*)uniform\s+(int|uint|bool|float)\s+([A-Za-z_]\w*)\s*;(.*)$)");
  std::smatch m;
  if (!std::regex_match(line, m, uniform_re)) return {};
  for (const auto& [name, value] : constants)
    if (m[3] == name) return m[1].str() + "const " + m[2].str() + ' ' + name + " = " + m[2].str() + '(' + value + ");" + m[4].str();
  return {};
}

std::vector<ShaderDiagnostic> parse_shader_log(const std::string& log, const std::vector<fs::path>& files) {
  // Mesa: "0:12(5): error: message" (or "preprocessor error:"); NVIDIA: "0(12) : error C1008: message";
  // AMD, Intel, Apple, glslang: "ERROR: 0:12: message" (WARNING: likewise).
  static const std::regex mesa_re(R"(^\s*\d+:(\d+)\((\d+)\): (?:preprocessor )?(error|warning): ?(.*)$)");
  static const std::regex nvidia_re(R"(^\s*\d+\((\d+)\) : (error|warning) ([A-Z]\d+: ?.*)$)");
  static const std::regex khronos_re(R"(^\s*(ERROR|WARNING): \d+:(\d+): ?(.*)$)");
  std::vector<ShaderDiagnostic> out;
  for (const auto& raw : split_lines(log)) {
    const std::string line = raw.empty() || raw.back() != '\r' ? raw : raw.substr(0, raw.size() - 1);
    std::smatch m;
    if (std::regex_match(line, m, mesa_re)) {
      // Mesa counts columns from 0; messages count them from 1, as g++ does.
      out.push_back(place(std::stoul(m[1]), std::stoi(m[2]) + 1, m[3] == "error", m[4], files));
    } else if (std::regex_match(line, m, nvidia_re)) {
      out.push_back(place(std::stoul(m[1]), 0, m[2] == "error", m[3], files));
    } else if (std::regex_match(line, m, khronos_re)) {
      out.push_back(place(std::stoul(m[2]), 0, m[1] == "ERROR", m[3], files));
    } else if (line.find_first_not_of(" \t") != std::string::npos) {
      ShaderDiagnostic d;
      d.error = line.find("warning") == std::string::npos;
      d.message = line;
      out.push_back(d);
    }
  }
  return out;
}

std::string ShaderDiagnostic::to_string() const {
  const char* severity = error ? "error" : "warning";
  if (file.empty()) return printable(message, 2000) + '\n';
  std::string out = (shown.empty() ? display_path(file) : shown) + ':' + std::to_string(line) + (column > 0 ? ':' + std::to_string(column) : "") + ": " +
                    severity + ": " + printable(message, 2000) + '\n';
  std::string text;
  if (line >= 1 && read_text(file, text)) {
    const auto source_lines = split_lines(text);
    if (static_cast<std::size_t>(line) <= source_lines.size())
      out += "    " + std::to_string(line) + " | " + printable(source_lines[static_cast<std::size_t>(line) - 1], 2000) + '\n';
  }
  return out;
}

namespace {

std::string join(const std::vector<ShaderDiagnostic>& diagnostics, bool errors) {
  std::string out;
  for (const auto& d : diagnostics)
    if (d.error == errors) out += d.to_string();
  return out;
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

GlShader compile_stage(GLenum type, const fs::path& path, const ProgramDesc& desc, ProgramBuild& build) {
  std::vector<fs::path> files;
  const std::string source = preprocess_shader(resolve(path), desc, files, build.error);
  build.files.insert(build.files.end(), files.begin(), files.end());
  if (!build.error.empty()) return {};
  GlShader shader = make_shader(type);
  const char* text = source.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  auto diagnostics = parse_shader_log(info_log(shader.id(), glGetShaderiv, glGetShaderInfoLog), files);
  const ShownNames names = shown_names(desc.rules);
  for (auto& d : diagnostics)
    if (!d.file.empty()) d.shown = shown_name(d.file, names);
  build.diagnostics.insert(build.diagnostics.end(), diagnostics.begin(), diagnostics.end());
  build.warnings += join(diagnostics, false);
  if (!succeeded(shader.id(), GL_COMPILE_STATUS, glGetShaderiv)) {
    build.error = join(diagnostics, true);
    if (build.error.empty()) build.error = shown_name(resolve(path), shown_names(desc.rules)) + ": compile failed with no log";
    return {};
  }
  return shader;
}

}  // namespace

std::string preprocess_shader(const fs::path& path, const ProgramDesc& desc, std::vector<fs::path>& files,
                              std::string& error) {
  Expander expander{desc, files, error, {}, {}, shown_names(desc.rules)};
  for (const auto& c : desc.rules.confined) expander.confined.insert(fs::weakly_canonical(resolve(c)));
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
    GlShader shader = compile_stage(stage.type, stage.path, desc, result);
    if (!shader) return result;
    shaders.push_back(std::move(shader));
  }
  GlProgram program = GlProgram::create();
  for (const auto& s : shaders) glAttachShader(program.id(), s.id());
  if (!desc.feedback_varyings.empty()) {
    std::vector<const char*> names;
    for (const auto& name : desc.feedback_varyings) names.push_back(name.c_str());
    glTransformFeedbackVaryings(program.id(), static_cast<GLsizei>(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
  }
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
  warnings_ = build.warnings;
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
