#include "labs/cpp_exercise.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "renderer/shader.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

// The compiler's and linker's words with our paths replaced by the names the student knows; at most
// `max_lines` lines.
std::string student_view(std::string log, const CppExerciseSpec& spec, const fs::path& work, std::size_t max_lines = 30) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(spec.source, ec);
  replace_all(log, canonical.string(), spec.display_name);
  replace_all(log, spec.source.string(), spec.display_name);
  replace_all(log, (work / "").string(), "");
  replace_all(log, (data_dir() / "").string(), "");
  auto lines = lines_of(log);
  std::string out;
  for (std::size_t i = 0; i < lines.size() && i < max_lines; ++i) out += lines[i] + "\n";
  if (lines.size() > max_lines) out += "... (" + std::to_string(lines.size() - max_lines) + " more lines)\n";
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// Includes, inline assembly: refused before the compiler reads anything the lab does not offer.
void screen_source(const std::string& text, const CppExerciseSpec& spec) {
  static const std::regex include_re(R"(^\s*#\s*include(.*)$)");
  static const std::regex quoted_re(R"re(^\s*"([^"]+)"\s*(//.*)?$)re");
  static const std::regex angled_re(R"(^\s*<([^>]+)>\s*(//.*)?$)");
  static const std::regex asm_re(R"(\b(asm|__asm|__asm__)\b\s*(volatile|__volatile__|goto|inline)?\s*\()");
  static const std::regex embed_re(R"(^\s*#\s*embed\b)");
  const auto lines = lines_of(text);
  std::string offered;
  for (const auto& h : spec.headers) offered += (offered.empty() ? "\"" : ", \"") + h + "\"";
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string where = spec.display_name + ":" + std::to_string(i + 1) + ": ";
    const std::string quote = "\n    " + std::to_string(i + 1) + " | " + lines[i];
    std::smatch m, arg;
    if (std::regex_match(lines[i], m, include_re)) {
      const std::string rest = m[1];
      if (std::regex_match(rest, arg, quoted_re)) {
        if (std::find(spec.headers.begin(), spec.headers.end(), arg[1].str()) == spec.headers.end())
          throw ExerciseError("compile_error", where + "error: this exercise may include only " + offered +
                                                   " and the system's <headers>" + quote);
      } else if (std::regex_match(rest, arg, angled_re)) {
        const std::string name = arg[1];
        if (name.front() == '/' || name.find("..") != std::string::npos)
          throw ExerciseError("compile_error", where + "error: includes by absolute path or with '..' are refused" + quote);
      } else {
        throw ExerciseError("compile_error", where + "error: an include must name its file as \"file\" or <file>" + quote);
      }
    }
    if (std::regex_search(lines[i], asm_re) || std::regex_search(lines[i], embed_re))
      throw ExerciseError("compile_error", where + "error: inline assembly and #embed are refused in exercises" + quote);
  }
}

// The outcome of a tool as an exception for the student (their code) or the grader (the tool).
void expect_success(const platform::ChildOutcome& o, const std::string& what, const fs::path& log,
                    const CppExerciseSpec& spec, const fs::path& work) {
  using Kind = platform::ChildOutcome::Kind;
  if (o.kind == Kind::NotStarted) throw std::runtime_error(what + ": " + o.error);
  if (o.kind == Kind::TimedOut)
    throw ExerciseError("timed_out", spec.display_name + ": " + what + " took longer than " +
                                         std::to_string(static_cast<int>(spec.compile_seconds)) + " s");
  if (o.kind == Kind::Exited && o.exit_code == 0) return;
  const std::string words = student_view(read_file(log), spec, work);
  if (o.kind == Kind::Signalled)
    throw std::runtime_error(what + " of " + spec.display_name + " died: " + o.signal_name + "\n" + words);
  throw ExerciseError("compile_error", words.empty() ? spec.display_name + ": " + what + " failed" : words);
}

}  // namespace

CppExercise::CppExercise(CppExerciseSpec spec) : spec_(std::move(spec)) {
  work_ = platform::make_private_temp_dir("shadowlab-exercise");
  try {
    build();
  } catch (...) {
    std::error_code ec;
    fs::remove_all(work_, ec);
    throw;
  }
}

CppExercise::~CppExercise() {
  child_.finish();
  std::error_code ec;
  fs::remove_all(work_, ec);
}

void CppExercise::build() {
  if (!fs::is_regular_file(spec_.source))
    throw std::runtime_error(spec_.display_name + ": not in the submission (" + spec_.source.string() + ")");
  screen_source(read_file(spec_.source), spec_);
  const platform::ChildLimits tool_limits{spec_.compile_seconds, 4ull << 30};

  // 1. Compile the student's file alone, with the grader's headers (quoted includes only) and flags.
  const fs::path object = work_ / "exercise.o", compile_log = work_ / "compile.log";
  std::vector<std::string> compile = {SHADOWLAB_CXX, "-fno-diagnostics-color",
                                      "-fmax-errors=10"};
  std::istringstream flags(SHADOWLAB_EXERCISE_CXX_FLAGS);
  for (std::string f; flags >> f;) compile.push_back(f);
  const fs::path pch = fs::path(SHADOWLAB_EXERCISE_HOST_DIR) / (spec_.host + ".h");
  if (fs::exists(pch.string() + ".gch")) {  // the lab's headers precompiled (labs/CMakeLists.txt)
    compile.push_back("-include");
    compile.push_back(pch.string());
  }
  for (const std::string& f : {std::string("-iquote"), data_dir().string(), std::string("-c"), spec_.source.string(),
                               std::string("-o"), object.string()})
    compile.push_back(f);
  expect_success(platform::run_child(compile, tool_limits, compile_log), "compiling", compile_log, spec_, work_);

  // 2. What the object calls and runs: only the offered functions of the grader, nothing before main.
  const fs::path symbols_log = work_ / "nm.log", sections_log = work_ / "objdump.log";
  expect_success(platform::run_child({"nm", "-C", "--undefined-only", object.string()}, tool_limits, symbols_log),
                 "listing the symbols", symbols_log, spec_, work_);
  std::set<std::string> refused;
  for (const auto& line : lines_of(read_file(symbols_log))) {
    const auto at = line.find("shadowlab::");
    if (at == std::string::npos) continue;
    const std::string name = line.substr(at, line.find('(', at) - at);
    if (std::find(spec_.offered.begin(), spec_.offered.end(), name) == spec_.offered.end()) refused.insert(name);
  }
  if (!refused.empty()) {
    std::string names, offered;
    for (const auto& n : refused) names += (names.empty() ? "" : ", ") + n;
    for (const auto& n : spec_.offered) offered += (offered.empty() ? "" : ", ") + n;
    throw ExerciseError("compile_error", spec_.display_name + ": error: calls " + names +
                                             ", which this exercise may not use; it may call " + offered);
  }
  expect_success(platform::run_child({"objdump", "-h", object.string()}, tool_limits, sections_log),
                 "listing the sections", sections_log, spec_, work_);
  static const std::regex init_re(R"(\s(\.init_array|\.preinit_array|\.ctors)\S*\s)");
  if (std::regex_search(read_file(sections_log), init_re))
    throw ExerciseError("compile_error", spec_.display_name +
                                             ": error: code that runs before the exercise is called (a global object "
                                             "with a constructor, or a constructor attribute): move it into the function");

  // 3. Link with the lab's host (its main and the protocol) and the renderer's CPU library.
  const fs::path program = work_ / "exercise", link_log = work_ / "link.log";
  const fs::path host = fs::path(SHADOWLAB_EXERCISE_HOST_DIR) / ("libshadowlab_exercise_host_" + spec_.host + ".a");
  if (!fs::exists(host)) throw std::runtime_error(host.string() + ": the lab's exercise host is not built (scripts/build)");
  expect_success(platform::run_child({SHADOWLAB_CXX, object.string(), host.string(), SHADOWLAB_CORE_LIBRARY,
                                      "-lseccomp", "-o", program.string()},
                                     tool_limits, link_log),
                 "linking", link_log, spec_, work_);

  // 4. Start it: it waits for calls.
  std::string error;
  if (!child_.start({program.string()}, {0.0, 1ull << 30}, work_ / "run.log", error)) throw std::runtime_error(error);
}

void CppExercise::call_raw(const void* request, std::size_t request_size, void* reply, std::size_t reply_size) {
  using Io = platform::PipeChild::Io;
  const Io io = child_.call(request, request_size, reply, reply_size, spec_.call_seconds);
  if (io == Io::Ok) return;
  const platform::ChildOutcome o = child_.finish();
  if (io == Io::TimedOut)
    throw ExerciseError("timed_out", spec_.display_name + ": the exercise did not return within " +
                                         std::to_string(static_cast<int>(spec_.call_seconds)) + " s (an endless loop?)");
  std::string how = o.kind == platform::ChildOutcome::Kind::Signalled
                        ? "crashed: " + o.signal_name
                        : "stopped before answering (exit code " + std::to_string(o.exit_code) + ")";
  const std::string printed = student_view(read_file(work_ / "run.log"), spec_, work_, 10);
  throw ExerciseError("crashed", spec_.display_name + ": the exercise " + how + (printed.empty() ? "" : "\n" + printed));
}

}  // namespace shadowlab
