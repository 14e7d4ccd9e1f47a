#include "grading/cpp_exercise.h"

#include "grading/check.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "grading/sandbox.h"
#include "core/platform.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSourceDir = SHADOWLAB_EXERCISE_SOURCE_DIR;  // where the lab's headers are
constexpr std::uint64_t kLogBytes = 4 << 20;  // what the running exercise may print, at most

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

std::string student_view(std::string log, const CppExerciseSpec& spec, const fs::path& work, std::size_t max_lines = 30) {
  return compiler_words(std::move(log), spec.source, spec.display_name, work, max_lines);
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
  if (o.kind == Kind::TimedOut || platform::stopped_at_cpu_limit(o, spec.compile_seconds))
    throw ExerciseError("timed_out", spec.display_name + ": " + what + " took longer than " +
                                         std::to_string(static_cast<int>(spec.compile_seconds)) + " s");
  if (o.kind == Kind::Exited && o.exit_code == 0) return;
  const std::string words = student_view(read_file(log), spec, work);
  if (o.kind == Kind::Signalled)
    throw ExerciseError("compile_error", spec.display_name + ": " + what + " was stopped: " + o.signal_name +
                                             (words.empty() ? "" : "\n" + words));
  throw ExerciseError("compile_error", words.empty() ? spec.display_name + ": " + what + " failed" : words);
}

// The student's file as bytes, refused when it or a folder on its way is a link (it could name any
// file the grader may read), when it is not a regular file, or when it is too big to be an exercise.
std::string read_submitted(const CppExerciseSpec& spec) {
  const std::string source = spec.source.generic_string(), name = fs::path(spec.display_name).generic_string();
  const bool named = source.size() > name.size() && source.compare(source.size() - name.size(), name.size(), name) == 0;
  fs::path at = named ? fs::path(source.substr(0, source.size() - name.size())) : spec.source.parent_path();
  fs::path inside;
  for (const auto& part : named ? fs::path(name) : spec.source.filename()) {
    at /= part;
    inside /= part;
    if (fs::is_symlink(at))
      throw ExerciseError("compile_error", spec.display_name + ": error: " + inside.generic_string() +
                                               " is a link; submit the file itself");
  }
  try {  // a FIFO or a device is refused before it is opened, a file too large before it is read
    return platform::read_regular_file(spec.source, kMaxExerciseSourceBytes);
  } catch (const platform::FileError& e) {
    if (e.problem() == platform::FileProblem::NotFound)
      throw ExerciseError("compile_error", spec.display_name + ": not in the submission");
    throw ExerciseError("compile_error", spec.display_name + ": error: " + e.what() + "; an exercise is a few KB of C++");
  }
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write");
}

// The grader's side of a build: the compiler and the files of ours the sandboxes may see.
struct Tools {
  std::string compiler;       // the real file (the sandbox has no /etc/alternatives to follow links through)
  fs::path pch, host, core;   // the lab's precompiled headers, its host library, the renderer's CPU library
  std::vector<fs::path> headers;  // every project header the lab's headers include (the PCH's dependencies)
  platform::ChildLimits limits;

  explicit Tools(const CppExerciseSpec& spec) {
    std::error_code ec;
    compiler = fs::canonical(SHADOWLAB_CXX, ec).string();
    if (ec || compiler.rfind("/usr/", 0) != 0)
      throw std::runtime_error(std::string(SHADOWLAB_CXX) + ": the compiler must be the system's (under /usr), which "
                               "is all a grading sandbox holds");
    const fs::path dir = SHADOWLAB_EXERCISE_HOST_DIR;
    pch = dir / (spec.host + ".h");
    host = dir / ("libshadowlab_exercise_host_" + spec.host + ".a");
    core = SHADOWLAB_CORE_LIBRARY;
    if (!fs::exists(host) || !fs::exists(pch.string() + ".d"))
      throw std::runtime_error(host.string() + ": the lab's exercise host is not built (scripts/build)");
    headers = project_headers(pch.string() + ".d");
    headers.push_back(pch);
    if (fs::exists(pch.string() + ".gch")) headers.push_back(pch.string() + ".gch");
    // The whole build (compiling and linking) within twice the time of one; each tool within one.
    limits = {2.0 * spec.compile_seconds, 4ull << 30, spec.compile_seconds, 256ull << 20};
  }

  // The files under the project's folder that the precompiled headers were made from (a make rule:
  // "target: dep dep \\ ..." with spaces in names escaped).
  static std::vector<fs::path> project_headers(const fs::path& depfile) {
    std::vector<fs::path> found;
    const std::string text = read_file(depfile), root = std::string(kSourceDir) + "/";
    std::string word;
    auto take = [&] {
      if (word.rfind(root, 0) == 0 && fs::is_regular_file(word)) found.emplace_back(word);
      word.clear();
    };
    for (std::size_t i = text.find(':') + 1; i < text.size(); ++i) {
      if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == ' ') word += text[++i];
      else if (text[i] == '\\' || std::isspace(static_cast<unsigned char>(text[i]))) take();
      else word += text[i];
    }
    take();
    return found;
  }

  platform::SandboxSpec toolchain(std::vector<platform::SandboxMount> mounts) const {
    platform::SandboxSpec spec;
    spec.system_toolchain = true;
    spec.filter = platform::SyscallFilter::Toolchain;
    spec.mounts = std::move(mounts);
    return spec;
  }
};

// A word for the shell, quoted: every argument of the build script is ours, but paths may hold spaces.
std::string quoted(const std::string& word) {
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string line;
  for (const auto& a : argv) line += (line.empty() ? "" : " ") + quoted(a);
  return line;
}

// What the build script left in /out (our work folder's out/): a file the tools wrote, never a link,
// at most 1 MB of it.
std::string build_file(const fs::path& out, const std::string& name) {
  const fs::path p = out / name;
  if (fs::is_symlink(p) || !fs::is_regular_file(p)) return "";
  std::ifstream in(p, std::ios::binary);
  std::string text(1u << 20, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// Calls into the grader's code other than the functions the lab offers (the solution is not one).
void refuse_calls(const std::string& undefined, const CppExerciseSpec& spec) {
  std::set<std::string> refused;
  for (const auto& line : lines_of(undefined)) {
    const auto at = line.find("shadowlab::");
    if (at == std::string::npos) continue;
    const std::string name = line.substr(at, line.find('(', at) - at);
    if (std::find(spec.offered.begin(), spec.offered.end(), name) == spec.offered.end()) refused.insert(name);
  }
  if (refused.empty()) return;
  std::string names, offered;
  for (const auto& n : refused) names += (names.empty() ? "" : ", ") + n;
  for (const auto& n : spec.offered) offered += (offered.empty() ? "" : ", ") + n;
  throw ExerciseError("compile_error", spec.display_name + ": error: calls " + names +
                                           ", which this exercise may not use; it may call " + offered);
}

// A line of `nm`: "0000000000000000 T name" -> {'T', "name"}; {0, ""} for anything else.
std::pair<char, std::string> nm_symbol(const std::string& line) {
  std::istringstream in(line);
  std::string address, type, name;
  if (!(in >> address >> type >> name) || type.size() != 1) return {0, ""};
  return {type[0], name};
}

// Definitions that would take the place of the grader's or the system's own functions: any C name
// (main, read, seccomp_load...), and what the lab's host library itself defines (not the inline
// functions both compile from the same headers, nor the compiler's own symbols such as
// DW.ref.__gxx_personality_v0, which no identifier can name).
void refuse_definitions(const std::string& defined, const std::string& host_defined, const CppExerciseSpec& spec) {
  std::set<std::string> host;
  for (const auto& line : lines_of(host_defined))
    if (const auto [type, name] = nm_symbol(line); std::string("TDBRG").find(type) != std::string::npos) host.insert(name);
  static const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
  std::set<std::string> refused;
  for (const auto& line : lines_of(defined))
    if (const auto [type, name] = nm_symbol(line);
        type && std::regex_match(name, identifier) && (name.rfind("_Z", 0) != 0 || host.count(name)))
      refused.insert(name);
  if (refused.empty()) return;
  std::string names;
  for (const auto& n : refused) names += (names.empty() ? "" : ", ") + n;
  throw ExerciseError("compile_error", spec.display_name + ": error: defines " + names +
                                           ", which the grader or the system provides; an exercise defines only "
                                           "the functions its TODO asks for and C++ helpers of its own");
}

}  // namespace

std::string compiler_words(std::string log, const fs::path& source, const std::string& display_name, const fs::path& work,
                           std::size_t max_lines) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(source, ec);
  replace_all(log, canonical.string(), display_name);
  replace_all(log, source.string(), display_name);
  replace_all(log, (work / "").string(), "");
  replace_all(log, (data_dir() / "").string(), "");
  replace_all(log, std::string(kSourceDir) + "/", "");
  auto lines = lines_of(log);
  std::string out;
  for (std::size_t i = 0; i < lines.size() && i < max_lines; ++i) out += lines[i] + "\n";
  if (lines.size() > max_lines) out += "... (" + std::to_string(lines.size() - max_lines) + " more lines)\n";
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::vector<std::string> exercise_compiler_command() {
  std::vector<std::string> argv = {SHADOWLAB_CXX};
  std::istringstream flags(SHADOWLAB_EXERCISE_CXX_FLAGS);
  for (std::string f; flags >> f;) argv.push_back(f);
  return argv;
}

std::string cpp_exercise_unavailable(const std::string& host) {
  if (const std::string& why = platform::sandbox_unavailable(); !why.empty()) return why;
  if (!fs::exists(fs::path(SHADOWLAB_EXERCISE_HOST_DIR) / ("libshadowlab_exercise_host_" + host + ".a")))
    return "this build has no exercise host for " + host +
           " (a GL exercise's is built only with EGL, on Linux; none is built with the sanitizers)";
  return "";
}

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
  const std::string text = read_submitted(spec_);
  if (spec_.screen) screen_source(text, spec_);
  if (const std::string& why = platform::sandbox_unavailable(); !why.empty())
    throw std::runtime_error(spec_.display_name + " is not graded: " + why);
  const Tools tools(spec_);
  // The sandbox sees the student's file as a copy in our work folder, at its place in the project.
  const fs::path copy = work_ / "exercise.cpp", out = work_ / "out";
  write_bytes(copy, text);
  fs::create_directory(out);
  platform::SandboxSpec sandbox = tools.toolchain(
      {{out, "/out", true}, {tools.host, "/grader/libhost.a"}, {tools.core, "/grader/libcore.a"}});
  for (const auto& header : tools.headers) sandbox.mounts.push_back({header, header.string()});
  sandbox.mounts.push_back({copy, (fs::path(kSourceDir) / spec_.display_name).string()});
  sandbox.chdir = kSourceDir;

  // One sandbox, one script (each sandbox costs a start-up): each step names itself in /out/step and
  // the first that fails ends it with its status.
  std::vector<std::string> compile = {tools.compiler, "-fno-diagnostics-color", "-fmax-errors=10"};
  std::istringstream flags(SHADOWLAB_EXERCISE_CXX_FLAGS);
  for (std::string f; flags >> f;) compile.push_back(f);
  if (fs::exists(tools.pch.string() + ".gch")) compile.insert(compile.end(), {"-include", tools.pch.string()});
  compile.insert(compile.end(), {"-iquote", kSourceDir, "-c", spec_.display_name, "-o", "/out/exercise.o"});
  // A GL exercise links the system's OpenGL dynamically (Mesa cannot be linked statically).
  std::vector<std::string> link = {tools.compiler, "-Wl,--gc-sections", "/out/exercise.o", "/grader/libhost.a", "/grader/libcore.a", "-lseccomp"};
  if (spec_.renders) link.insert(link.end(), {"-lepoxy", "-lEGL"});
  else link.insert(link.begin() + 1, "-static");
  link.insert(link.end(), {"-o", "/out/exercise"});
  const std::string script =
      // 1. Compile it alone, with the lab's headers (precompiled) and nothing else of ours.
      "echo compiling >/out/step; " + command_line(compile) + " >/out/compiling.log 2>&1 || exit $?\n"
      // 2. What the object calls, defines and runs before main, for the friendly refusals.
      "echo listing >/out/step; exec 2>/out/listing.log\n"
      "nm -C --undefined-only /out/exercise.o >/out/undefined.txt || exit $?\n"
      "nm --defined-only --extern-only /out/exercise.o >/out/defined.txt || exit $?\n"
      "nm --defined-only --extern-only /grader/libhost.a >/out/host.txt || exit $?\n"
      "objdump -h /out/exercise.o >/out/sections.txt || exit $?\n"
      // 3. Link it (statically, but for a GL exercise: above) with the lab's host (its main and the protocol) and the renderer's CPU
      // library: the program then needs nothing but itself to run. Only what it calls is kept (the core
      // has a section per function): the labs' solutions, which share files with the functions an
      // exercise may call, are not in the program for it to find.
      "echo linking >/out/step; " +
      command_line(link) +
      " >/out/linking.log 2>&1 || exit $?\n";
  const platform::SandboxCommand command(sandbox, {"/bin/sh", "-c", script});
  const platform::ChildOutcome built = platform::inner_outcome(
      platform::run_child(command.argv(), tools.limits, work_ / "build.log", {}, command.inherited()));
  std::string step = build_file(out, "step");
  while (!step.empty() && std::isspace(static_cast<unsigned char>(step.back()))) step.pop_back();
  if (spec_.screen && (step == "linking" || (built.kind == platform::ChildOutcome::Kind::Exited && built.exit_code == 0)))
    screen_object(out);
  if (step.empty()) step = "starting the build";
  expect_success(built, step, out / (step + ".log"), spec_, work_);

  // 4. Start it in a sandbox holding only the program, under the computing-only filter: it waits for calls.
  platform::SandboxSpec alone;
  alone.mounts = {{out / "exercise", "/exercise"}};
  alone.filter = platform::SyscallFilter::Computing;
  if (spec_.renders) {  // the system's libraries and Mesa's files, one thread, no shader cache on disk
    alone.system_toolchain = true;
    alone.filter = platform::SyscallFilter::Toolchain;
    alone.env = {{"LP_NUM_THREADS", "0"}, {"MESA_SHADER_CACHE_DISABLE", "true"}};
  }
  const platform::SandboxCommand run(alone, {"/exercise"});
  std::string error;
  const platform::ChildLimits limits{0.0, 1ull << 30, 0.0, kLogBytes};
  if (!child_.start(run.argv(), limits, work_ / "run.log", error, run.inherited())) throw std::runtime_error(error);
}

// The friendly refusals of what the object calls, defines and runs before main, from the build's lists.
void CppExercise::screen_object(const fs::path& out) const {
  refuse_calls(build_file(out, "undefined.txt"), spec_);
  refuse_definitions(build_file(out, "defined.txt"), build_file(out, "host.txt"), spec_);
  static const std::regex init_re(R"(\s(\.init_array|\.preinit_array|\.ctors)\S*\s)");
  if (std::regex_search(build_file(out, "sections.txt"), init_re))
    throw ExerciseError("compile_error", spec_.display_name +
                                             ": error: code that runs before the exercise is called (a global object "
                                             "with a constructor, or a constructor attribute): move it into the function");
}

void CppExercise::call_raw(const void* request, std::size_t request_size, void* reply, std::size_t reply_size) {
  using Io = platform::PipeChild::Io;
  const Io io = child_.call(request, request_size, reply, reply_size, spec_.call_seconds);
  if (io == Io::Ok) return;
  const platform::ChildOutcome o = platform::inner_outcome(child_.finish());
  if (io == Io::TimedOut)
    throw ExerciseError("timed_out", spec_.display_name + ": the exercise did not return within " +
                                         std::to_string(static_cast<int>(spec_.call_seconds)) + " s (an endless loop?)");
  std::string how = o.kind == platform::ChildOutcome::Kind::Signalled
                        ? "crashed: " + o.signal_name
                        : "stopped before answering (exit code " + std::to_string(o.exit_code) + ")";
  const std::string printed = student_view(read_file(work_ / "run.log"), spec_, work_, 10);
  throw ExerciseError("crashed", spec_.display_name + ": the exercise " + how + (printed.empty() ? "" : "\n" + printed));
}

// The local student flow (grading/check.h): an exercise file edited since the build is graded from disk,
// built on its own as a submission's is.
std::vector<std::string> CheckContext::grade_edited_cpp_files() {
  std::vector<std::string> notes;
  for (auto& file : graded) {
    const auto copy = lab.compiled_copies.find(file.generic_string());
    if (copy == lab.compiled_copies.end()) continue;
    const std::filesystem::path on_disk = data_dir() / file;
    std::string text;
    try {  // a FIFO or a device is refused before it is opened, a file too large before it is read
      text = platform::read_regular_file(on_disk, kMaxExerciseSourceBytes);
    } catch (const std::exception& e) {
      throw ExerciseError("compile_error", copy->first + ": " + e.what());
    }
    if (without_carriage_returns(text) == without_carriage_returns(std::string(copy->second))) continue;
    if (const std::string why = platform::grading_unavailable(); !why.empty())
      throw ExerciseError("compile_error", copy->first + " has changed since this shadowlab was built: rebuild it "
                                               "(cmake --build build), then Check again (on Linux, Check builds an edited "
                                               "C++ exercise on its own; here " + why + ")");
    notes.push_back(copy->first + " differs from the copy built into this program: graded from the file on disk, "
                    "compiled on its own (as a submission is)");
    file = std::filesystem::absolute(on_disk);
  }
  return notes;
}

}  // namespace shadowlab
