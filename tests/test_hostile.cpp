// Hostile input, round two (issue 18): every finding kept as a test. The models are made in code
// (tests/hostile_cases.cpp); so are the races. CPU only; scripts/test runs these under ASan+UBSan too.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/gltf_loader.h"
#include "core/image_io.h"
#include "core/platform.h"
#include "core/untrusted.h"
#include "tests/gltf_doc.h"
#include "tests/hostile_cases.h"
#include "tests/test_util.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;
using namespace shadowlab::test;

class Hostile : public TempDirTest {};

// No byte a terminal acts on: control characters, DEL, C1 controls (as UTF-8), NUL.
bool printable_line(const std::string& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7F) return false;
    if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
        static_cast<unsigned char>(s[i + 1]) <= 0x9F)
      return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------
// Every hostile model: a refusal naming the file and the problem, one printable line of bounded length.

TEST_F(Hostile, EveryCaseIsRefusedClearly) {
  const std::vector<HostileCase> cases = write_hostile_cases(dir_ / "cases");
  ASSERT_GE(cases.size(), 20u);
  for (const HostileCase& c : cases) {
    SCOPED_TRACE(c.name + " (" + c.issue_item + ")");
    const auto start = std::chrono::steady_clock::now();
    const std::string message = load_error(c.file);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_NE(message, "") << "loaded";
    EXPECT_EQ(message.rfind(c.file.string() + ": ", 0), 0u) << "names the file first: " << message.substr(0, 300);
    EXPECT_NE(message.find(c.must_mention), std::string::npos) << message.substr(0, 2000);
    EXPECT_TRUE(printable_line(message)) << message.substr(0, 2000);
    EXPECT_LT(message.size(), 2000u);
    std::printf("[   case   ] %-26s %6.3f s  %4zu-byte message\n", c.name.c_str(), seconds, message.size());
  }
}

TEST_F(Hostile, UnknownPropertiesAreIgnoredWithAWarning) {
  Doc d = triangle_doc();
  d.j["nodes"][0]["light"] = 3;
  d.j["lights"] = json::array();
  std::vector<std::string> warnings;
  EXPECT_EQ(load_gltf(d.write(dir_ / "unknown.gltf"), {}, &warnings).triangle_count(), 1u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "lights is not a glTF 2.0 glTF property; ignored");
  EXPECT_EQ(warnings[1], "nodes[0].light is not a glTF 2.0 node property; ignored");
}

TEST_F(Hostile, LimitsAreNamedAndMovable) {
  // Each limit refuses at its own value, and a file within it loads.
  const fs::path file = triangle_doc(kUnsignedShort).write(dir_ / "tri.gltf");
  EXPECT_NE(load_error(file, LoadLimits{.max_json_bytes = 10}).find("(LoadLimits::max_json_bytes"), std::string::npos);
  EXPECT_NE(load_error(file, LoadLimits{.max_json_depth = 2}).find("deeper than 2 levels (LoadLimits::max_json_depth)"),
            std::string::npos);
  EXPECT_NE(load_error(file, LoadLimits{.max_json_values = 10}).find("more than 10 values (LoadLimits::max_json_values)"),
            std::string::npos);
  EXPECT_NE(load_error(file, LoadLimits{.max_objects = 1}).find("2 accessors, above the limit of 1 (LoadLimits::max_objects)"),
            std::string::npos);
  EXPECT_NE(load_error(file, LoadLimits{.max_instances = 0}).find("more than 0 mesh primitives (one per node instance; LoadLimits::max_instances)"),
            std::string::npos);
  EXPECT_NE(load_error(file, LoadLimits{.max_coordinate = 0.5}).find("(LoadLimits::max_coordinate)"), std::string::npos);
  EXPECT_EQ(load_error(file, LoadLimits{.max_json_depth = 6, .max_instances = 1, .max_coordinate = 1.0}), "");
}

// ---------------------------------------------------------------------------------------------------
// 5. A symbolic link swapped in the model's folder while it loads: 10,000 loads, nothing read outside.
// The swapper renames links over `sub` (a folder on the path) or `link.bin` (the file itself), between
// a target inside the folder and one outside it; the outside triangle is 100 units away, so a load that
// read it would show. Before the fix (URI checked by path, then opened by path) 289 of 3,000 tries read
// outside.

struct RaceCounts {
  int inside = 0, refused = 0, outside = 0, other = 0;
};

RaceCounts race(const fs::path& dir, const std::string& swapped, const std::string& uri, const std::string& in_target,
                const std::string& out_target, int tries) {
  Doc d = triangle_doc();
  write_bytes(dir / "outside/tri.bin", [] {
    Doc far;
    far.vec3s({{100, 100, 100}, {101, 100, 100}, {100, 101, 100}});
    return far.bin;
  }());
  write_bytes(dir / "model/real/tri.bin", d.bin);
  write_bytes(dir / "model/tri.bin", d.bin);
  d.buffer(uri);
  const fs::path model = d.write(dir / "model/model.gltf");
  const fs::path link = dir / "model" / swapped, tmp = dir / "model" / (swapped + ".new");
  fs::create_symlink(in_target, link);
  std::atomic<bool> stop{false};
  std::thread swapper([&] {
    for (bool out = true; !stop; out = !out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      fs::create_symlink(out ? out_target : in_target, tmp, ec);
      fs::rename(tmp, link, ec);  // atomic: `swapped` always exists, pointing one way or the other
    }
  });
  RaceCounts counts;
  for (int i = 0; i < tries; ++i) {
    try {
      const Scene scene = load_gltf(model);
      const double x = scene.origin.x + scene.meshes.at(0).positions.at(0).x;  // the world's (a far model keeps its origin)
      (x < 50 ? counts.inside : counts.outside) += 1;
    } catch (const LoadError& e) {
      const std::string m = e.what();
      (m.find("outside the folder") != std::string::npos ? counts.refused : counts.other) += 1;
      if (m.find("outside the folder") == std::string::npos && counts.other < 3) std::printf("other: %s\n", m.c_str());
    }
  }
  stop = true;
  swapper.join();
  return counts;
}

TEST_F(Hostile, SymlinkSwappedWhileLoadingNeverReadsOutside) {
  const int tries = 10'000;
  for (const auto& [swapped, uri, in_target, out_target] :
       std::vector<std::tuple<std::string, std::string, std::string, std::string>>{
           {"sub", "sub/tri.bin", "real", "../outside"},
           {"link.bin", "link.bin", "tri.bin", "../outside/tri.bin"},
           {"abs", "abs/tri.bin", "real", (dir_ / "outside").string()}}) {
    SCOPED_TRACE(swapped + " -> " + in_target + " | " + out_target);
    fs::remove_all(dir_ / "model");
    const RaceCounts c = race(dir_, swapped, uri, in_target, out_target, tries);
    std::printf("[   race   ] %-8s %d tries: %d loaded inside, %d refused (outside), %d read outside, %d other\n",
                swapped.c_str(), tries, c.inside, c.refused, c.outside, c.other);
    EXPECT_EQ(c.outside, 0);
    EXPECT_EQ(c.inside + c.refused + c.other, tries);
    // The race was run: both targets were met (how often depends on the scheduler: 1-50% here).
    EXPECT_GE(c.inside, 10);
    EXPECT_GE(c.refused, 10);
  }
}

// ---------------------------------------------------------------------------------------------------
// Confinement: what the folder handle allows and refuses.

TEST_F(Hostile, FolderReadStaysInside) {
  fs::create_directories(dir_ / "m/a/b");
  write_all(dir_ / "m/a/b/f.bin", "inside");
  write_all(dir_ / "secret.bin", "outside");
  fs::create_symlink("b/f.bin", dir_ / "m/a/rel_link");       // relative, stays inside
  fs::create_symlink("../../secret.bin", dir_ / "m/a/escape");  // relative, leaves
  fs::create_symlink(dir_ / "m/a/b/f.bin", dir_ / "m/abs");     // absolute, even when inside
  fs::create_symlink("loop2", dir_ / "m/loop1");
  fs::create_symlink("loop1", dir_ / "m/loop2");
  ::mkfifo((dir_ / "m/pipe").c_str(), 0600);
  const platform::Folder folder(dir_ / "m");
  using platform::FileProblem;
  const auto problem = [&](const std::string& rel) {
    try {
      folder.read(rel, 1000);
    } catch (const platform::FileError& e) {
      return e.problem();
    }
    return FileProblem::Io;  // read: not what these cases expect
  };
  EXPECT_EQ(folder.read("a/b/f.bin", 1000), "inside");
  EXPECT_EQ(folder.read("a/./b/../b/f.bin", 1000), "inside");
  EXPECT_EQ(folder.read("a/rel_link", 1000), "inside");
  EXPECT_EQ(folder.read("a/b/f.bin", 0), "") << "checked, not read";
  EXPECT_EQ(problem("../secret.bin"), FileProblem::Outside);
  EXPECT_EQ(problem("a/../../secret.bin"), FileProblem::Outside);
  EXPECT_EQ(problem("a/escape"), FileProblem::Outside);
  EXPECT_EQ(problem("abs"), FileProblem::Outside);
  EXPECT_EQ(problem("/etc/hostname"), FileProblem::Outside);
  EXPECT_EQ(problem("loop1"), FileProblem::Io);  // too many links
  EXPECT_EQ(problem("pipe"), FileProblem::NotRegular);
  EXPECT_EQ(problem("a"), FileProblem::NotRegular);
  EXPECT_EQ(problem("a/b/f.bin/x"), FileProblem::NotFound);
  EXPECT_EQ(problem("nothing.bin"), FileProblem::NotFound);
  try {
    folder.read("a/b/f.bin", 3);
    ADD_FAILURE() << "read past max_bytes";
  } catch (const platform::FileError& e) {
    EXPECT_EQ(e.problem(), FileProblem::TooLarge);
  }
}

TEST_F(Hostile, DevicesAndFifosAreRefusedBeforeReading) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe.gltf").c_str(), 0600), 0);
  for (const fs::path& p : {dir_ / "pipe.gltf", fs::path("/dev/zero"), fs::path("/dev/null"), dir_}) {
    const auto start = std::chrono::steady_clock::now();
    const std::string message = load_error(p);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << p;
    EXPECT_NE(message.find("not a regular file"), std::string::npos) << message;
  }
}

// ---------------------------------------------------------------------------------------------------
// 9. Outputs: nothing written through a link the output folder did not create.

TEST_F(Hostile, OutputsNeverWriteThroughPlantedLinks) {
  const fs::path out = dir_ / "out", victim = dir_ / "victim.txt";
  fs::create_directories(out);
  write_all(victim, "precious");
  for (const char* name : {"final.png", "final.png.tmp", "render.json", "render.json.tmp", "position.npy",
                           ".shadowlab-write-test"})
    fs::create_symlink(victim, out / name);
  write_png(out / "final.png", 2, 2, std::vector<std::uint8_t>(16, 255));
  write_text_atomic(out / "render.json", "{}\n");
  write_npy(out / "position.npy", 1, 1, 1, {1.0f});
  platform::probe_writable(out);
  EXPECT_EQ(read_all(victim), "precious");
  for (const char* name : {"final.png", "render.json", "position.npy"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out / name))) << name << " replaced the link";
  }
  EXPECT_EQ(read_all(out / "final.png").substr(1, 3), "PNG");
  EXPECT_EQ(read_all(out / "render.json"), "{}\n");
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << "temporary file left: " << e.path();
}

// 6. Two processes locking one output folder: the second is told who holds it; the holder may take it
// again; once the holder is gone the folder is free.
TEST_F(Hostile, OutputFolderLockIsExclusiveBetweenProcesses) {
  int ready[2], done[2];
  ASSERT_EQ(::pipe(ready), 0);
  ASSERT_EQ(::pipe(done), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::string holder;
    const bool ok = platform::lock_folder(dir_, &holder) && platform::lock_folder(dir_, &holder);
    const char c = ok ? 'y' : 'n';
    (void)!::write(ready[1], &c, 1);
    char wait = 0;
    (void)!::read(done[0], &wait, 1);
    std::_Exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_EQ(c, 'y');
  std::string holder;
  EXPECT_FALSE(platform::lock_folder(dir_, &holder));
  EXPECT_EQ(holder, std::to_string(child));
  (void)!::write(done[1], "x", 1);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(platform::lock_folder(dir_, &holder)) << "free once the holder exited";
  for (int fd : {ready[0], ready[1], done[0], done[1]}) ::close(fd);
}

// ---------------------------------------------------------------------------------------------------
// 10. Untrusted text.

TEST(UntrustedText, EscapesWhatTerminalsActOnAndCuts) {
  EXPECT_EQ(printable("plain/path with spaces.bin"), "plain/path with spaces.bin");
  EXPECT_EQ(printable("a\x1b[2Jb\nc\r\td"), "a\\x1B[2Jb\\nc\\r\\td");
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable("C1 \xC2\x9B" "2J"), "C1 \\u009B2J");
  EXPECT_EQ(printable("bidi \xE2\x80\xAE" "txt.exe"), "bidi \\u202Etxt.exe");
  EXPECT_EQ(printable("bad \xFF\xC0\xAF utf-8"), "bad \\xFF\\xC0\\xAF utf-8");
  EXPECT_EQ(printable("é ü 漢字 🙂"), "é ü 漢字 🙂");
  EXPECT_EQ(printable(std::string(1000, 'x'), 10), std::string(10, 'x') + "... (1000 bytes)");
  const std::string once = printable("\x1b[31mred\\n");
  EXPECT_EQ(printable(once), once) << "idempotent";
  EXPECT_EQ(quote("a'b"), "'a'b'");
  EXPECT_EQ(shortened("é" + std::string(10, 'x'), 1), "... (12 bytes in all; the whole message is on the terminal)")
      << "never cuts inside a character";
}

TEST(UntrustedText, JsonIsParsedWithinItsLimits) {
  const JsonLimits limits{.max_depth = 64, .max_values = 1000};
  const auto error = [&](const std::string& text) -> std::string {
    try {
      parse_json_bounded(text, limits);
    } catch (const JsonShapeError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(parse_json_bounded(std::string(64, '[') + std::string(64, ']'), limits).dump().size(), 128u);
  EXPECT_EQ(error(std::string(65, '[') + std::string(65, ']')), "the JSON nests arrays and objects deeper than 64 levels");
  EXPECT_EQ(error(std::string(1'000'000, '[')), "the JSON nests arrays and objects deeper than 64 levels");
  EXPECT_EQ(error("{\"a\":" + std::string(100, '[') + std::string(100, ']') + "}"),
            "the JSON nests arrays and objects deeper than 64 levels");
  std::string many = "[0";
  for (int i = 0; i < 998; ++i) many += ",0";
  EXPECT_EQ(parse_json_bounded(many + "]", limits).size(), 999u) << "999 numbers and their array: 1000 values";
  EXPECT_EQ(error(many + ",0]"), "the JSON holds more than 1000 values");
  EXPECT_NE(error("{\"a\": [1, 2"), "") << "not JSON";
  EXPECT_NE(error("{\"a\": [1, 2").find("parse error"), std::string::npos);
}

}  // namespace
}  // namespace shadowlab
