// Compile errors point at the student's line, whatever the error's kind and wherever the file sits in
// the include tree; the three common driver log formats are placed alike; a student's file includes
// only what its lab offers.
#include <gtest/gtest.h>

#ifndef _WIN32
#include <sys/stat.h>  // mkfifo
#include <unistd.h>    // getpid
#endif

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/live_cpp.h"
#include "grading/cpp_exercise.h"
#include "labs/registry.h"
#include "renderer/renderer.h"
#include "core/scene.h"
#include "renderer/shader.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// One kind of mistake: the lines a student writes into a `float student(float x)` function, the line
// (1-based, within those lines) the compiler must point at, and something the message must mention.
struct Mistake {
  const char* kind;
  const char* body;
  int line;
};

// Mesa's messages differ by kind; the test holds the location to the student's file and line.
const Mistake kMistakes[] = {
    {"undeclared identifier", "  float y = x * 2.0;\n  return nope;\n", 2},
    {"redeclaration", "  float a = x;\n  float a = 2.0;\n  return a;\n", 2},
    {"type mismatch in an initialiser", "  float y = x;\n  float v = vec3(1.0);\n  return y;\n", 2},
    {"missing semicolon", "  float y = x;\n  y = y * 2.0 return y;\n", 2},
    {"wrong number of arguments", "  float y = x;\n  return max(y);\n", 2},
    {"call to an undefined function", "  float y = x;\n  return shadow_lookup(y);\n", 2},
    {"assignment to a constant", "  const float k = 1.0;\n  k = x;\n  return k;\n", 2},
    {"returning the wrong type", "  float y = x;\n  return vec2(y);\n", 2},
    {"unknown type", "  float y = x;\n  vec5 v;\n  return y;\n", 2},
    {"float to int without a cast", "  float y = x;\n  int i = y;\n  return y;\n", 2},
    {"swizzle out of range", "  vec2 v = vec2(x);\n  return v.z;\n", 2},
    {"#error directive", "  float y = x;\n#error not finished yet\n  return y;\n", 2},
    {"break outside a loop", "  float y = x;\n  break;\n  return y;\n", 2},
    {"constant index out of range", "  float a[2] = float[2](x, x);\n  return a[3];\n", 2},
};

class CompileErrorTest : public GlTest, public ::testing::WithParamInterface<Mistake> {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    dir = fs::temp_directory_path() / ("shadowlab-compile-errors-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    write("grader.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    // The grader's stage, like shaders/lit.frag: a few lines, then the lab's include, then more.
    write("grader.frag",
          "#version 330 core\n// the grader's own lines\nout vec4 o;\n#include \"lab/student.glsl\"\n"
          "void main() {\n  o = vec4(student(gl_FragCoord.x));\n}\n");
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
  ProgramBuild build(const fs::path& student, const std::string& helper_file = "") {
    ProgramDesc desc{dir / "grader.vert", {}, dir / "grader.frag", {}, {{"lab/student.glsl", student}}, {}};
    desc.rules.confined = {student};
    if (!helper_file.empty()) {
      desc.includes["lab/helper.glsl"] = dir / helper_file;
      desc.rules.offered = {"lab/helper.glsl"};
    }
    return build_program(desc);
  }
  fs::path dir;
};

TEST_P(CompileErrorTest, InTheExerciseFileTheStudentsLineIsNamed) {
  const Mistake& m = GetParam();
  // Three lines of preamble, so the error's line differs from the grader's and from 1.
  const int header = 3;
  write("exercise.glsl", std::string("// exercise\nuniform float u_scale;\n\nfloat student(float x) {\n") + m.body + "}\n");
  const ProgramBuild b = build(dir / "exercise.glsl");
  ASSERT_FALSE(b.program) << m.kind << " compiled";
  const std::string where = "exercise.glsl:" + std::to_string(header + 1 + m.line) + ":";
  EXPECT_NE(b.error.find(where), std::string::npos) << m.kind << ": expected " << where << " in\n" << b.error;
  EXPECT_EQ(b.error.find("grader.frag:"), std::string::npos) << m.kind << ": blamed the grader's file\n" << b.error;
  // The quoted line is the student's.
  std::string quoted = m.body;
  for (int i = 1; i < m.line; ++i) quoted = quoted.substr(quoted.find('\n') + 1);
  quoted = quoted.substr(0, quoted.find('\n'));
  EXPECT_NE(b.error.find(std::to_string(header + 1 + m.line) + " | " + quoted), std::string::npos) << b.error;
}

TEST_P(CompileErrorTest, InAFileTheExerciseIncludesThatFileIsNamed) {
  const Mistake& m = GetParam();
  write("helper.glsl", std::string("// a helper the student wrote\nfloat helper(float x) {\n") + m.body + "}\n");
  write("exercise.glsl", "// exercise\n#include \"lab/helper.glsl\"\nfloat student(float x) { return helper(x); }\n");
  const ProgramBuild b = build(dir / "exercise.glsl", "helper.glsl");
  ASSERT_FALSE(b.program) << m.kind << " compiled";
  const std::string where = "helper.glsl:" + std::to_string(2 + m.line) + ":";
  EXPECT_NE(b.error.find(where), std::string::npos) << m.kind << ": expected " << where << " in\n" << b.error;
  EXPECT_EQ(b.error.find("exercise.glsl:"), std::string::npos) << b.error;
}

INSTANTIATE_TEST_SUITE_P(Kinds, CompileErrorTest, ::testing::ValuesIn(kMistakes),
                         [](const ::testing::TestParamInfo<Mistake>& info) {
                           std::string name;
                           for (const char* c = info.param.kind; *c; ++c)
                             name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
                           return name;
                         });

TEST_F(CompileErrorTest, WarningsArePlacedToo) {
  // Mesa warns when an uninitialised variable is read: the student's line again. Mesa's shader cache
  // gives no log for a shader it has compiled before, so this source is new on every run.
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  write("exercise.glsl", "// exercise " + std::to_string(now) + "\nfloat student(float x) {\n  float y;\n  return y + x;\n}\n");
  const ProgramBuild b = build(dir / "exercise.glsl");
  ASSERT_TRUE(b.program) << b.error;
  EXPECT_NE(b.warnings.find("exercise.glsl:4:"), std::string::npos) << b.warnings;
  EXPECT_NE(b.warnings.find("warning:"), std::string::npos) << b.warnings;
}

// The column counts from 1, as g++'s do: the driver's (Mesa's counts from 0) plus one. `nope` starts
// at the line's 10th character.
TEST_F(CompileErrorTest, ColumnsCountFromOne) {
  write("exercise.glsl", "// exercise\nfloat student(float x) {\n  float y = x;\n  return nope;\n}\n");
  const ProgramBuild b = build(dir / "exercise.glsl");
  ASSERT_FALSE(b.program);
  ASSERT_FALSE(b.diagnostics.empty());
  EXPECT_EQ(b.diagnostics[0].line, 4);
  EXPECT_EQ(b.diagnostics[0].column, 10) << b.error;
  EXPECT_NE(b.error.find("exercise.glsl:4:10: error:"), std::string::npos) << b.error;
}

// A submission graded from a folder anywhere (check --submission DIR): its files are named as the
// project names them, labs/NN_slug/file:line:col, in the renderer's error (the window's panel), the
// check's error and its JSON; DIR itself appears in no message. A compile error, an include refusal,
// and an error in the second slot of a two-file lab (lab 3's Chebyshev half, included by the lab's file).
TEST_F(GlTest, ASubmissionsMessagesNameItsFilesAsTheProjectDoes) {
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-submission-" + std::to_string(::getpid())) / "alice";
  struct Case {
    int lab;
    std::string file, text, where;
  };
  const Case cases[] = {
      {0, "labs/00_basic_shadow_map/exercise.glsl",
       "// alice\n#include \"lab/bias.glsl\"\nfloat shadow_visibility(vec3 p, vec3 n, float d) {\n  return nope;\n}\n",
       "labs/00_basic_shadow_map/exercise.glsl:4:10: error: "},
      {0, "labs/00_basic_shadow_map/exercise.glsl", "// alice\n  #include \"shadow/hard.glsl\"\n",
       "labs/00_basic_shadow_map/exercise.glsl:2:12: error: #include \"shadow/hard.glsl\" is not offered"},
      {3, "labs/03_vsm_setup/exercise_chebyshev.glsl",
       "// alice\nfloat chebyshev_upper_bound(vec2 m, float z) {\n  return nope;\n}\n",
       "labs/03_vsm_setup/exercise_chebyshev.glsl:3:10: error: "},
  };
  const Scene scene = make_default_scene();
  for (const Case& c : cases) {
    fs::remove_all(dir);
    const Lab& lab = *find_lab(c.lab);
    for (std::size_t i = 0; i < lab.exercise_files.size(); ++i) {  // the solution's files in the other slots
      fs::create_directories((dir / lab.exercise_files[i]).parent_path());
      fs::copy_file(data_dir() / lab.solution_files[i], dir / lab.exercise_files[i]);
    }
    std::ofstream(dir / c.file, std::ios::trunc) << c.text;
    Renderer renderer;
    CheckRun run;
    run.submission = dir;
    const CheckResult result = run_lab_check(renderer, lab, scene, run);
    EXPECT_EQ(result.status(), CheckStatus::CompileError) << result.error;
    const std::string json_error = result.to_json()["error"].get<std::string>();
    SlotFiles files;  // the window's panel shows what set_features reports
    for (const auto& f : lab.exercise_files) files.push_back(dir / f);
    Renderer window;
    EXPECT_FALSE(window.set_features(lab.hooks_for(files)));
    const std::string panel = window.shader_error();
    for (const std::string& text : {result.error, json_error, panel}) {
      EXPECT_NE(text.find(c.where), std::string::npos) << "expected " << c.where << " in\n" << text;
      EXPECT_EQ(text.find(dir.parent_path().string()), std::string::npos) << "the grading machine's path in\n" << text;
    }
  }
  fs::remove_all(dir.parent_path());
}

// Each driver's log format, placed in the same file table: file k's line n is k * stride + n.
// Every GLSL lab through the renderer: a syntax error in each exercise file is reported with that file's
// name (its slot's exercise file as the project names it, not the path of the copy), although most labs
// switch the renderer to another shadow pass, one that is not kept when it does not build (its error was
// once lost, and lab 5's broken blur was graded "failed" with no reason).
TEST_F(GlTest, EveryLabsBrokenExerciseIsReportedByTheRenderer) {
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-broken-exercises-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  int graded = 0;
  for (const Lab& lab : all_labs()) {
    const SlotFiles stock = lab.files(Impl::Exercise);
    for (std::size_t slot = 0; slot < stock.size(); ++slot) {
      if (stock[slot].extension() != ".glsl") continue;  // lab 2's exercise is C++
      SlotFiles files = lab.files(Impl::Solution);
      const fs::path broken = dir / (std::to_string(lab.number) + "_" + stock[slot].filename().string());
      std::ifstream in(data_dir() / stock[slot]);
      std::ofstream(broken) << in.rdbuf() << "\nint broken_on_purpose = ;\n";
      files[slot] = broken;
      Renderer renderer;  // starts on its default technique, as the check and the window do
      EXPECT_FALSE(renderer.set_features(lab.hooks_for(files))) << "lab " << lab.number << " built a broken file";
      // Named as the exercise file of its slot, wherever the broken copy sits.
      EXPECT_NE(renderer.shader_error().find(stock[slot].generic_string() + ":"), std::string::npos)
          << "lab " << lab.number << ": the error does not name " << stock[slot] << ":\n"
          << renderer.shader_error();
      EXPECT_EQ(renderer.shader_error().find(dir.string()), std::string::npos) << renderer.shader_error();
      ++graded;
    }
  }
  fs::remove_all(dir);
  EXPECT_GE(graded, 10);  // labs 0, 1, 3 (two files), 4-9
}

// A uniform compiled as a constant (the lit program for a lab's settings): only a line declaring that
// uniform alone becomes a constant of the same type, keeping its indentation and trailing comment.
TEST(ShaderConstants, OnlyALoneDeclarationOfTheNameBecomesAConstant) {
  const std::vector<std::pair<std::string, std::string>> c = {{"u_pcf_radius", "2"}, {"u_pcf_hardware", "1"}};
  EXPECT_EQ(uniform_as_constant("uniform int u_pcf_radius;    // (N - 1) / 2", c),
            "const int u_pcf_radius = int(2);    // (N - 1) / 2");
  EXPECT_EQ(uniform_as_constant("  uniform bool u_pcf_hardware ;", c), "  const bool u_pcf_hardware = bool(1);");
  EXPECT_EQ(uniform_as_constant("uniform float u_pcf_radius;", c), "const float u_pcf_radius = float(2);");
  EXPECT_EQ(uniform_as_constant("uniform int u_pcf_radius2;", c), "");
  EXPECT_EQ(uniform_as_constant("uniform int u_pcf_radius, u_other;", c), "");
  EXPECT_EQ(uniform_as_constant("// uniform int u_pcf_radius;", c), "");
  EXPECT_EQ(uniform_as_constant("uniform sampler2D u_pcf_radius;", c), "");
  EXPECT_EQ(uniform_as_constant("uniform int u_blur_radius;", c), "");
}

TEST(ShaderLog, EveryCommonDriverFormatIsPlaced) {
  const std::vector<fs::path> files = {"shaders/lit.frag", "labs/06_pcf/exercise.glsl"};
  const int line = kShaderLineStride + 12;
  struct Case {
    const char* driver;
    std::string log;
    int column;
    bool error;
  };
  const Case cases[] = {
      // Mesa counts columns from 0, messages from 1 (as g++ does).
      {"Mesa", "0:" + std::to_string(line) + "(7): error: `nope' undeclared", 8, true},
      {"Mesa, another source string", "3:" + std::to_string(line) + "(7): error: `nope' undeclared", 8, true},
      {"Mesa warning", "0:" + std::to_string(line) + "(3): warning: `y' used uninitialized", 4, false},
      {"NVIDIA", "0(" + std::to_string(line) + ") : error C1008: undefined variable \"nope\"", 0, true},
      {"NVIDIA warning", "0(" + std::to_string(line) + ") : warning C7050: \"y\" might be used before being initialized", 0,
       false},
      {"AMD / Intel / Apple / glslang", "ERROR: 0:" + std::to_string(line) + ": 'nope' : undeclared identifier", 0, true},
      {"glslang warning", "WARNING: 0:" + std::to_string(line) + ": 'y' : used before set", 0, false},
      {"Windows line ending", "ERROR: 0:" + std::to_string(line) + ": 'nope' : undeclared identifier\r", 0, true},
  };
  for (const auto& c : cases) {
    const auto d = parse_shader_log(c.log + "\n", files);
    ASSERT_EQ(d.size(), 1u) << c.driver;
    EXPECT_EQ(d[0].file, files[1]) << c.driver;
    EXPECT_EQ(d[0].line, 12) << c.driver;
    EXPECT_EQ(d[0].column, c.column) << c.driver;
    EXPECT_EQ(d[0].error, c.error) << c.driver;
    EXPECT_NE(d[0].to_string().find("labs/06_pcf/exercise.glsl:12"), std::string::npos) << d[0].to_string();
  }
  // A line no format matches is kept, unplaced, rather than lost.
  const auto other = parse_shader_log("error: linking failed\n", files);
  ASSERT_EQ(other.size(), 1u);
  EXPECT_TRUE(other[0].file.empty());
  EXPECT_EQ(other[0].to_string(), "error: linking failed\n");
}

// A student's file includes only what its lab offers: no solution, no absolute path, no "..".
class IncludeConfinementTest : public CompileErrorTest {};

TEST_F(IncludeConfinementTest, OnlyOfferedNamesAreFollowed) {
  write("helper.glsl", "float helper(float x) { return x; }\n");
  write("secret.glsl", "this line must never be quoted\n");
  const std::pair<const char*, const char*> refused[] = {
      {"shadow/pcf.glsl", "is not offered by this lab"},
      {"solution.glsl", "is not offered by this lab"},
      {"/etc/passwd", "an absolute path is not allowed"},
      {"../secret.glsl", "may not leave its folder"},
      {"lab/../secret.glsl", "may not leave its folder"},
  };
  for (const auto& [name, why] : refused) {
    write("exercise.glsl", std::string("// exercise\n#include \"") + name + "\"\nfloat student(float x) { return x; }\n");
    const ProgramBuild b = build(dir / "exercise.glsl", "helper.glsl");
    EXPECT_FALSE(b.program) << name;
    EXPECT_NE(b.error.find("exercise.glsl:2:"), std::string::npos) << b.error;
    EXPECT_NE(b.error.find(why), std::string::npos) << name << ": " << b.error;
    EXPECT_EQ(b.error.find("must never be quoted"), std::string::npos) << b.error;
    EXPECT_EQ(b.error.find("root:"), std::string::npos) << b.error;
  }
  write("exercise.glsl", "// exercise\n#include \"lab/helper.glsl\"\nfloat student(float x) { return helper(x); }\n");
  const ProgramBuild ok = build(dir / "exercise.glsl", "helper.glsl");
  EXPECT_TRUE(ok.program) << ok.error;
}

// An offered renderer file (lab 7 offers shadow/slope.glsl) is read from the renderer's shaders, never
// from a copy planted beside the student's file.
TEST_F(IncludeConfinementTest, AnOfferedRendererFileIsTheRenderers) {
  fs::create_directories(dir / "shadow");
  write("shadow/slope.glsl", "this planted line must never be compiled\n");
  write("exercise.glsl", "// exercise\n#include \"shadow/slope.glsl\"\n"
                         "float student(float x) { return shadow_tan_incidence(x); }\n");
  ProgramDesc desc{dir / "grader.vert", {}, dir / "grader.frag", {}, {{"lab/student.glsl", dir / "exercise.glsl"}}, {}};
  desc.rules.confined = {dir / "exercise.glsl"};
  desc.rules.offered = {"shadow/slope.glsl"};
  const ProgramBuild b = build_program(desc);
  EXPECT_TRUE(b.program) << b.error;
  desc.rules.offered.clear();
  const ProgramBuild refused = build_program(desc);
  EXPECT_FALSE(refused.program);
  EXPECT_NE(refused.error.find("is not offered by this lab"), std::string::npos) << refused.error;
}

TEST_F(IncludeConfinementTest, AnIncludeMayEndInAComment) {
  write("helper.glsl", "float helper(float x) { return x; }\n");
  write("exercise.glsl", "// exercise\n#include \"lab/helper.glsl\"  // the helper\nfloat student(float x) { return helper(x); }\n");
  const ProgramBuild ok = build(dir / "exercise.glsl", "helper.glsl");
  EXPECT_TRUE(ok.program) << ok.error;
}

#ifndef _WIN32  // no FIFOs on native Windows
// A student's "file" that is a FIFO is refused, not read (reading it would block for ever).
TEST_F(IncludeConfinementTest, AFifoIsNotRead) {
  ASSERT_EQ(::mkfifo((dir / "exercise.glsl").c_str(), 0600), 0);
  const ProgramBuild b = build(dir / "exercise.glsl");
  EXPECT_FALSE(b.program);
  EXPECT_NE(b.error.find("not a regular file"), std::string::npos) << b.error;
}

// The window's live C++ path reads the exercise as Check does: a FIFO in its place is refused by name at
// once (never opened, so the poll cannot block), and so is a file over the exercise size limit; nothing
// is built from either, and the program's copy keeps running.
TEST(LiveCppExercise, AFifoOrAHugeFileIsRefusedNotRead) {
  const fs::path data = fs::temp_directory_path() / ("shadowlab-live-fifo-" + std::to_string(::getpid()));
  const fs::path lab_dir = data / "labs" / "02_ortho_fit";
  fs::create_directories(lab_dir);
  const char* old = std::getenv("SHADOWLAB_DATA_DIR");
  const std::string saved = old ? old : "";
  ::setenv("SHADOWLAB_DATA_DIR", data.c_str(), 1);
  const Lab& lab = *find_lab(2);
  ASSERT_EQ(lab.exercise_files.size(), 1u);
  const fs::path file = data / lab.exercise_files[0];
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  {
    LiveCppExercise live;
    const auto start = std::chrono::steady_clock::now();
    live.poll(lab, Impl::Exercise);  // would block for ever if the FIFO were opened
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_FALSE(live.building());
    EXPECT_NE(live.message().find("exercise.cpp"), std::string::npos) << live.message();
    EXPECT_NE(live.message().find("not a regular file"), std::string::npos) << live.message();
    EXPECT_NE(live.message().find("the program's copy keeps running"), std::string::npos) << live.message();
    EXPECT_FALSE(live.take_hooks());
  }
  fs::remove(file);
  std::ofstream(file, std::ios::binary) << std::string(kMaxExerciseSourceBytes + 1, ' ');
  {
    LiveCppExercise live;
    live.poll(lab, Impl::Exercise);
    EXPECT_FALSE(live.building());
    EXPECT_TRUE(live.has_error()) << live.message();
    EXPECT_NE(live.message().find("exercise.cpp"), std::string::npos) << live.message();
    EXPECT_FALSE(live.take_hooks());
  }
  // Lab 0's GL exercise, which the window builds into itself: the same refusal, even when asked to wait
  // for the first build (start-up), and nothing is compiled or loaded.
  const Lab& gl_lab = *find_lab(0);
  ASSERT_EQ(gl_lab.gl_exercise_files.size(), 1u);
  const fs::path gl_file = data / gl_lab.gl_exercise_files[0];
  fs::create_directories(gl_file.parent_path());
  ASSERT_EQ(::mkfifo(gl_file.c_str(), 0600), 0);
  {
    LiveCppExercise live;
    const auto start = std::chrono::steady_clock::now();
    live.poll(gl_lab, Impl::Exercise, true);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_FALSE(live.building());
    EXPECT_NE(live.message().find("gl_shadow_target.cpp"), std::string::npos) << live.message();
    EXPECT_NE(live.message().find("not a regular file"), std::string::npos) << live.message();
    EXPECT_FALSE(live.take_hooks());
  }
  if (old) ::setenv("SHADOWLAB_DATA_DIR", saved.c_str(), 1); else ::unsetenv("SHADOWLAB_DATA_DIR");
  fs::remove_all(data);
}
#endif

// Through a real lab: lab 6's exercise, as a submission's file that includes the renderer's own PCF.
TEST_F(IncludeConfinementTest, AnExerciseCannotIncludeTheSolution) {
  const Lab& pcf = *find_lab(6);
  const fs::path submitted = dir / "labs" / "06_pcf" / "exercise.glsl";
  fs::create_directories(submitted.parent_path());
  std::ofstream(submitted) << "// borrowing the answer\n#include \"shadow/pcf.glsl\"\n";
  Renderer r;
  EXPECT_FALSE(r.set_features(pcf.hooks_for({submitted})));
  EXPECT_NE(r.shader_error().find("exercise.glsl:2:"), std::string::npos) << r.shader_error();
  EXPECT_NE(r.shader_error().find("not offered"), std::string::npos) << r.shader_error();
  // The solution itself may include what it likes.
  EXPECT_TRUE(r.set_features(pcf.hooks(Impl::Solution))) << r.shader_error();
}

}  // namespace
}  // namespace shadowlab
