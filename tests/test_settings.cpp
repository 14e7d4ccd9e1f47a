// Settings are never lost: round trip, bad files kept aside, a crash between write and rename, a folder
// that cannot be written. CPU only.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/settings.h"
#include "core/params.h"
#include "tests/test_util.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

using test::read_all;
using test::write_all;

std::vector<fs::path> backups_of(const fs::path& file) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(file.parent_path()))
    if (e.path().filename().string().rfind(file.filename().string() + ".bad-", 0) == 0) found.push_back(e.path());
  return found;
}

// The temporary files beside `file` (".settings.json.tmp-<pid>-<random>").
std::vector<fs::path> temporaries_of(const fs::path& file) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(file.parent_path()))
    if (e.path().filename().string().rfind("." + file.filename().string() + ".tmp-", 0) == 0) found.push_back(e.path());
  return found;
}

class SettingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::path(::testing::TempDir()) / ("shadowlab-settings-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    file = dir / "config" / "shadowlab" / "settings.json";
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, ec);
    if (fs::exists(dir / "config")) fs::permissions(dir / "config" / "shadowlab", fs::perms::owner_all, ec);
    fs::remove_all(dir, ec);
  }
  static ParamSet params() { return ParamSet(renderer_param_specs()); }

  // Saves settings holding shadow.bias = `bias` for lab 1.
  void save_bias(double bias) {
    Settings s = Settings::load(file);
    ParamSet p = params();
    p.set("shadow.bias", bias);
    s.store_lab(1, p);
    s.save();
  }
  double loaded_bias() {
    const Settings s = Settings::load(file);
    EXPECT_EQ(s.warning(), "");
    ParamSet p = params();
    EXPECT_TRUE(s.apply_lab(1, p).empty());
    return p.get("shadow.bias");
  }

  fs::path dir, file;
};

TEST_F(SettingsTest, RoundTripKeepsValuesPresetsAndOtherLabs) {
  Settings s = Settings::load(file);  // first run: no file, no warning
  EXPECT_EQ(s.warning(), "");
  EXPECT_FALSE(s.dirty());
  ParamSet p = params();
  p.apply_assignment("shadow.bias=0.02");
  p.apply_assignment("shadow.cull=front");
  p.apply_assignment("shadow.map_size=2048");
  s.store_lab(1, p);
  p.apply_assignment("light.elevation=12");
  s.save_preset(1, "grazing light", p);
  EXPECT_TRUE(s.dirty());
  s.save();  // creates config/shadowlab/
  EXPECT_FALSE(s.dirty());
  EXPECT_TRUE(temporaries_of(file).empty());

  const nlohmann::json on_disk = nlohmann::json::parse(read_all(file));
  EXPECT_EQ(on_disk["version"], kSettingsVersion);

  // A lab this build does not know survives a load and a save untouched.
  nlohmann::json with_future_lab = on_disk;
  with_future_lab["labs"]["42"] = {{"params", {{"future.knob", 3}}}};
  write_all(file, with_future_lab.dump());

  Settings again = Settings::load(file);
  EXPECT_EQ(again.warning(), "");
  ParamSet q = params();
  EXPECT_TRUE(again.apply_lab(1, q).empty());
  EXPECT_DOUBLE_EQ(q.get("shadow.bias"), 0.02);
  EXPECT_EQ(q.get_choice("shadow.cull"), "front");
  EXPECT_EQ(q.get_choice("shadow.map_size"), "2048");
  EXPECT_DOUBLE_EQ(q.get("light.elevation"), params().get("light.elevation")) << "the preset's change is not the lab's";
  EXPECT_EQ(again.preset_names(1), std::vector<std::string>{"grazing light"});
  EXPECT_TRUE(again.load_preset(1, "grazing light", q).empty());
  EXPECT_DOUBLE_EQ(q.get("light.elevation"), 12.0);

  ParamSet other = params();
  other.set("shadow.bias", 0.05);
  EXPECT_TRUE(again.apply_lab(0, other).empty());
  EXPECT_DOUBLE_EQ(other.get("shadow.bias"), params().get("shadow.bias")) << "a lab without settings starts at its defaults";

  again.store_lab(0, other);
  again.save();
  EXPECT_EQ(nlohmann::json::parse(read_all(file))["labs"]["42"]["params"]["future.knob"], 3);
}

TEST_F(SettingsTest, PresetsAreSavedReplacedAndDeletedByName) {
  Settings s = Settings::load(file);
  ParamSet p = params();
  p.set("shadow.bias", 0.01);
  s.save_preset(2, "b", p);
  s.save_preset(2, "a", p);
  p.set("shadow.bias", 0.03);
  s.save_preset(2, "b", p);  // same name: replaced
  EXPECT_EQ(s.preset_names(2), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(s.preset_names(1).empty()) << "presets are per lab";
  ParamSet q = params();
  s.load_preset(2, "b", q);
  EXPECT_DOUBLE_EQ(q.get("shadow.bias"), 0.03);
  EXPECT_THROW(s.load_preset(2, "nope", q), std::invalid_argument);
  EXPECT_THROW(s.save_preset(2, "  ", p), std::invalid_argument);
  s.delete_preset(2, "a");
  EXPECT_EQ(s.preset_names(2), std::vector<std::string>{"b"});

  s.save_preset(2, "bad \xff utf-8", p);  // a name that is not UTF-8 cannot block saving
  EXPECT_NO_THROW(s.save());
  EXPECT_EQ(Settings::load(file).preset_names(2).size(), 2u);
}

// Corrupt, empty (what a truncating crash would leave), wrong shape: each is kept aside, byte for byte,
// with a warning naming both files, and the labs start from their defaults.
TEST_F(SettingsTest, BadFileIsKeptAsideWithAWarningAndDefaultsAreUsed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"version\": 1, \"labs\": {\"1\": {\"params\": {\"shadow.bias\": 0.0", "not valid JSON"},
      {"", "not valid JSON"},
      {"[1, 2]", "not a JSON object"},
      {"{\"labs\": {}}", "no version"},
      {"{\"version\": 1, \"labs\": []}", "not an object"},
      {"{\"version\": \"1\", \"labs\": {}}", "no version"},
      {"{\"version\": 1.5, \"labs\": {}}", "no version"},
  };
  for (const auto& [text, reason] : cases) {
    SCOPED_TRACE(text);
    fs::remove_all(file.parent_path());
    fs::create_directories(file.parent_path());
    write_all(file, text);
    Settings s = Settings::load(file);
    EXPECT_NE(s.warning().find(reason), std::string::npos) << s.warning();
    EXPECT_NE(s.warning().find("defaults are used"), std::string::npos) << s.warning();
    EXPECT_EQ(s.warning().find('\n'), std::string::npos) << "one line";
    const auto backups = backups_of(file);
    ASSERT_EQ(backups.size(), 1u);
    EXPECT_NE(s.warning().find(backups[0].string()), std::string::npos) << "says where the old file went";
    EXPECT_EQ(read_all(backups[0]), text);
    EXPECT_FALSE(fs::exists(file));

    ParamSet p = params();
    p.set("shadow.bias", 0.05);
    EXPECT_TRUE(s.apply_lab(1, p).empty());
    EXPECT_DOUBLE_EQ(p.get("shadow.bias"), params().get("shadow.bias"));
    s.store_lab(1, p);
    s.save();  // the next save writes a good file beside the backup
    EXPECT_EQ(Settings::load(file).warning(), "");
    EXPECT_EQ(backups_of(file).size(), 1u);
  }
}

TEST_F(SettingsTest, UnknownVersionIsKeptAside) {
  fs::create_directories(file.parent_path());
  const std::string newer = R"({"version": 2, "labs": {"1": {"params": {"shadow.bias": 0.02}}}})";
  write_all(file, newer);
  Settings s = Settings::load(file);
  EXPECT_NE(s.warning().find("has version 2; this build reads version 1"), std::string::npos) << s.warning();
  ASSERT_EQ(backups_of(file).size(), 1u);
  EXPECT_EQ(read_all(backups_of(file)[0]), newer);
  ParamSet p = params();
  s.apply_lab(1, p);
  EXPECT_DOUBLE_EQ(p.get("shadow.bias"), params().get("shadow.bias"));

  // A second bad file the same second gets a name of its own; neither backup is overwritten.
  write_all(file, "garbage");
  (void)Settings::load(file);
  EXPECT_EQ(backups_of(file).size(), 2u);
}

TEST_F(SettingsTest, ValuesThatNoLongerApplyAreReportedAndTheRestApplied) {
  fs::create_directories(file.parent_path());
  write_all(file, R"({"version": 1, "labs": {"1": {"params": {"shadow.bias": 0.02, "shadow.bais": 1, "light.elevation": 500}}}})");
  const Settings s = Settings::load(file);
  EXPECT_EQ(s.warning(), "");
  ParamSet p = params();
  const auto problems = s.apply_lab(1, p);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("settings for lab 1"), std::string::npos) << problems[0];
  EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.02);
  EXPECT_DOUBLE_EQ(p.get("light.elevation"), params().get("light.elevation"));
}

// One bad entry (issue 18): it is dropped alone, named in the warning; every other lab's values and
// presets are kept and written back on the next save; the file as it was is copied aside once.
TEST_F(SettingsTest, BadEntriesAreDroppedAloneAndTheRestIsWrittenBack) {
  fs::create_directories(file.parent_path());
  const std::string text = R"({"version": 1.0, "labs": {
      "1": {"params": {"shadow.bias": 0.02}, "presets": {"good": {"shadow.bias": 0.03}, "x": 3}},
      "2": 5,
      "3": {"params": [], "presets": {"kept": {"shadow.bias": 0.04}}},
      "4": {"params": {"shadow.bias": 0.01}, "presets": "nope"}}})";
  write_all(file, text);
  Settings s = Settings::load(file);
  const std::string w = s.warning();
  for (const char* part : {"lab '2' is not an object", "lab '3' params are not an object", "lab '1' preset 'x' is not an object",
                           "lab '4' presets are not an object", "the other settings are kept"})
    EXPECT_NE(w.find(part), std::string::npos) << part << " in: " << w;
  EXPECT_EQ(w.find('\n'), std::string::npos) << "one line";
  ASSERT_EQ(backups_of(file).size(), 1u);
  EXPECT_EQ(read_all(backups_of(file)[0]), text) << "the file as it was, byte for byte";
  EXPECT_NE(w.find(backups_of(file)[0].string()), std::string::npos);
  EXPECT_EQ(read_all(file), text) << "loading alone changes nothing on disk";

  ParamSet p = params();
  EXPECT_TRUE(s.apply_lab(1, p).empty());
  EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.02);
  EXPECT_EQ(s.preset_names(1), std::vector<std::string>{"good"});
  EXPECT_EQ(s.preset_names(3), std::vector<std::string>{"kept"});
  EXPECT_TRUE(s.apply_lab(4, p).empty());
  EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.01);
  EXPECT_TRUE(s.dirty()) << "what was dropped is written back at the next save";
  s.save();

  const Settings again = Settings::load(file);
  EXPECT_EQ(again.warning(), "") << "dropped once: the saved file is clean";
  EXPECT_EQ(again.document()["version"], 1);
  EXPECT_FALSE(again.document()["labs"].contains("2"));
  EXPECT_EQ(again.preset_names(1), std::vector<std::string>{"good"});
  EXPECT_EQ(again.preset_names(3), std::vector<std::string>{"kept"});
  EXPECT_EQ(backups_of(file).size(), 1u);
}

// The window's camera is kept with the scene it looked at, round trip exact; another scene gets none.
TEST_F(SettingsTest, CameraIsKeptForItsScene) {
  {
    Settings s = Settings::load(file);
    EXPECT_FALSE(s.camera("default").has_value()) << "none stored yet";
    OrbitCamera c = OrbitCamera::looking({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 2.0f}, 45.0f, {{-5, -1, -5}, {5, 2, 5}});
    c.fov_y_deg = 37.5f;
    s.store_camera("learnopengl", c);
    s.store_lab(1, params());
    s.save();
  }
  const Settings s = Settings::load(file);
  EXPECT_EQ(s.warning(), "");
  ASSERT_TRUE(s.camera("learnopengl").has_value());
  const OrbitCamera c = *s.camera("learnopengl");
  const OrbitCamera expected = OrbitCamera::looking({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 2.0f}, 45.0f, {{-5, -1, -5}, {5, 2, 5}});
  EXPECT_EQ(c.target, expected.target);
  EXPECT_EQ(c.eye(), expected.eye());
  EXPECT_EQ(c.fov_y_deg, 37.5f);
  EXPECT_EQ(c.near_plane, expected.near_plane);
  EXPECT_EQ(c.far_plane, expected.far_plane);
  EXPECT_FALSE(s.camera("default").has_value()) << "a camera is for the scene it looked at";
}

// A stored camera that is not one is dropped alone (the labs' values stay), named in the warning, and
// the file as it was is kept aside.
TEST_F(SettingsTest, BadCameraIsDroppedAlone) {
  fs::create_directories(file.parent_path());
  const std::string good = R"("target": [0, 0, 0], "distance": 3, "yaw_deg": 0, "pitch_deg": 10, "fov_y_deg": 45, "near_plane": 0.1, "far_plane": 50)";
  struct Case {
    std::string camera, why;
  };
  const Case cases[] = {{"[1, 2]", "is not an object"},
                        {"{" + good + "}", "has no scene name"},
                        {R"({"scene": "default", "target": [0, 0], "distance": 3})", "has no target"},
                        {R"({"scene": "default", "target": [0, "x", 0], "distance": 3})", "not three finite numbers"},
                        {R"({"scene": "default", "target": [0, 0, 0], "distance": 3})", "lacks a finite"},
                        {R"({"scene": "default", "target": [0, 0, 0], "distance": -3, "yaw_deg": 0, "pitch_deg": 10, "fov_y_deg": 45, "near_plane": 0.1, "far_plane": 50})", "distance"},
                        {R"({"scene": "default", "target": [0, 0, 0], "distance": 3, "yaw_deg": 0, "pitch_deg": 100, "fov_y_deg": 45, "near_plane": 0.1, "far_plane": 50})", "pitch"},
                        {R"({"scene": "default", "target": [0, 0, 0], "distance": 3, "yaw_deg": 0, "pitch_deg": 10, "fov_y_deg": 0, "near_plane": 0.1, "far_plane": 50})", "field of view"},
                        {R"({"scene": "default", "target": [0, 0, 0], "distance": 3, "yaw_deg": 0, "pitch_deg": 10, "fov_y_deg": 45, "near_plane": 5, "far_plane": 1})", "near < far"}};
  for (const auto& c : cases) {
    fs::remove_all(file.parent_path());
    fs::create_directories(file.parent_path());
    const std::string text = R"({"version": 1, "labs": {"1": {"params": {"shadow.bias": 0.02}}}, "camera": )" + c.camera + "}";
    write_all(file, text);
    Settings s = Settings::load(file);
    EXPECT_NE(s.warning().find("the camera " ), std::string::npos) << c.camera << ": " << s.warning();
    EXPECT_NE(s.warning().find(c.why), std::string::npos) << c.camera << ": " << s.warning();
    EXPECT_FALSE(s.camera("default").has_value()) << c.camera;
    ASSERT_EQ(backups_of(file).size(), 1u) << c.camera;
    EXPECT_EQ(read_all(backups_of(file)[0]), text);
    ParamSet p = params();
    EXPECT_TRUE(s.apply_lab(1, p).empty());
    EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.02) << "the labs' values stay";
  }
  write_all(file, R"({"version": 1, "labs": {}, "camera": {"scene": "default", )" + good + "}}");
  const Settings s = Settings::load(file);
  EXPECT_EQ(s.warning(), "");
  ASSERT_TRUE(s.camera("default").has_value());
  EXPECT_FLOAT_EQ(s.camera("default")->distance, 3.0f);
}

// The panel's text size is kept for every lab, round trip exact; one that is not a number in 0.5-3 is
// dropped alone (the labs' values stay), named in the warning.
TEST_F(SettingsTest, TextSizeIsKept) {
  {
    Settings s = Settings::load(file);
    EXPECT_FALSE(s.text_size().has_value()) << "none stored yet";
    s.store_text_size(1.75f);
    s.save();
  }
  EXPECT_EQ(Settings::load(file).text_size(), 1.75f);
  for (const std::string bad : {R"("big")", "9", "0.1", "null"}) {
    write_all(file, R"({"version": 1, "labs": {"1": {"params": {"shadow.bias": 0.02}}}, "ui": {"text_size": )" + bad + "}}");
    const Settings s = Settings::load(file);
    EXPECT_NE(s.warning().find("the text size is not a number in 0.5-3"), std::string::npos) << bad << ": " << s.warning();
    EXPECT_FALSE(s.text_size().has_value()) << bad;
    ParamSet p = params();
    EXPECT_TRUE(s.apply_lab(1, p).empty());
    EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.02) << "the labs' values stay";
  }
}

// The command line's values are shown, not saved: what is saved for each is the value it replaced,
// until the user changes it in the window; then the user's value is saved, as any other.
TEST(OneOffValues, SavedOnlyOnceChangedInTheWindow) {
  ParamSet saved(renderer_param_specs());
  saved.set("shadow.bias", 0.002);  // as the settings file had them
  saved.set("shadow.slope_bias", 2.0);
  ParamSet given = saved;
  given.set("shadow.bias", 0.05);   // --set shadow.bias=0.05
  given.set("shadow.slope_bias", 0.0);  // --preset's second value
  OneOffValues one_off;
  one_off.give(1, saved, given);

  ParamSet shown = given;
  EXPECT_DOUBLE_EQ(one_off.to_save(1, shown).get("shadow.bias"), 0.002) << "the --set value must not be saved";
  EXPECT_DOUBLE_EQ(one_off.to_save(1, shown).get("shadow.slope_bias"), 2.0);
  EXPECT_DOUBLE_EQ(one_off.to_save(2, shown).get("shadow.bias"), 0.05) << "one-off values are the given lab's";

  shown.set("shadow.bias", 0.01);  // the user moves the slider: the value is theirs now
  EXPECT_DOUBLE_EQ(one_off.to_save(1, shown).get("shadow.bias"), 0.01);
  shown.set("shadow.bias", 0.05);  // and back to the command line's value: still theirs
  EXPECT_DOUBLE_EQ(one_off.to_save(1, shown).get("shadow.bias"), 0.05);
  EXPECT_DOUBLE_EQ(one_off.to_save(1, shown).get("shadow.slope_bias"), 2.0)
      << "the value the user left alone is still one-off";

  // Leaving the lab and coming back: the settings' values, then the given ones still one-off over them.
  ParamSet reopened(renderer_param_specs());
  reopened.set("shadow.slope_bias", 3.0);
  one_off.reapply(1, reopened);
  EXPECT_DOUBLE_EQ(reopened.get("shadow.slope_bias"), 0.0);
  EXPECT_DOUBLE_EQ(one_off.to_save(1, reopened).get("shadow.slope_bias"), 3.0);
}

TEST(OneOffValues, CameraKeptOnceMoved) {
  OneOffValues one_off;
  OrbitCamera given;
  given.fov_y_deg = 40.0f;
  EXPECT_FALSE(one_off.camera_given(given)) << "no --camera: every camera is kept";
  one_off.give_camera(given);
  OrbitCamera same = given;
  same.near_plane = 0.5f;  // the planes follow the orbit; the camera did not move
  EXPECT_TRUE(one_off.camera_given(same));
  OrbitCamera moved = given;
  moved.yaw_deg += 10.0f;
  EXPECT_FALSE(one_off.camera_given(moved));
  EXPECT_FALSE(one_off.camera_given(given)) << "once moved, the camera is the user's, even back where it was";
}

// A value nested 100,000 deep (a 200 KB file) used to crash every start: it is dropped alone, the
// rest kept. A file that is nothing but nesting is moved aside once.
TEST_F(SettingsTest, DeepNestingIsDroppedNotCrashedOn) {
  fs::create_directories(file.parent_path());
  const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
  write_all(file, R"({"version": 1, "labs": {"0": {"params": {"shadow.bias": 0.02}}, "1": {"params": {"shadow.bias": )" +
                      deep + "}}}}");
  Settings s = Settings::load(file);
  EXPECT_NE(s.warning().find("the value at 'labs/1/params/shadow.bias' nests deeper than 32 levels"), std::string::npos)
      << s.warning();
  ParamSet p = params();
  EXPECT_TRUE(s.apply_lab(0, p).empty());
  EXPECT_DOUBLE_EQ(p.get("shadow.bias"), 0.02);
  s.save();
  EXPECT_EQ(Settings::load(file).warning(), "");
  EXPECT_LT(fs::file_size(file), 1000u);

  for (const std::size_t levels : {100'000u, 1'000'000u}) {
    fs::remove_all(file.parent_path());
    fs::create_directories(file.parent_path());
    write_all(file, std::string(levels, '[') + std::string(levels, ']'));
    const Settings bad = Settings::load(file);
    EXPECT_NE(bad.warning().find("is not a JSON object; kept as"), std::string::npos) << bad.warning();
    EXPECT_EQ(backups_of(file).size(), 1u);
    EXPECT_EQ(Settings::load(file).warning(), "") << "moved aside once: the next start finds no file";
  }
}

// Not a regular file: a FIFO would block a plain open forever; it is refused unopened, and nothing is
// written over it.
TEST_F(SettingsTest, FifoIsRefusedWithoutWaiting) {
  fs::create_directories(file.parent_path());
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  Settings s = Settings::load(file);
  EXPECT_NE(s.warning().find("is a FIFO, not a regular file"), std::string::npos) << s.warning();
  s.store_lab(1, params());
  EXPECT_THROW(s.save(), std::runtime_error);
  EXPECT_TRUE(fs::is_fifo(file));
}

// Two windows saving at once (issue 18: "cannot replace the settings file", a shared temporary name):
// every save of both succeeds and the file is always whole.
TEST_F(SettingsTest, ConcurrentSavesAllSucceed) {
  save_bias(0.01);
  std::atomic<int> failures{0};
  const auto saver = [&](double bias) {
    Settings s = Settings::load(file);
    ParamSet p = params();
    for (int i = 0; i < 200; ++i) {
      p.set("shadow.bias", bias + i * 1e-5);
      s.store_lab(1, p);
      try {
        s.save();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "save failed: %s\n", e.what());
        ++failures;
      }
    }
  };
  std::thread a(saver, 0.02), b(saver, 0.04);
  int whole = 0;
  for (int i = 0; i < 200; ++i) whole += nlohmann::json::parse(read_all(file), nullptr, false).is_discarded() ? 0 : 1;
  a.join();
  b.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(whole, 200) << "a reader saw a half-written file";
  EXPECT_TRUE(temporaries_of(file).empty());
  const double bias = loaded_bias();
  EXPECT_TRUE(std::abs(bias - (0.02 + 199e-5)) < 1e-9 || std::abs(bias - (0.04 + 199e-5)) < 1e-9) << bias;
}

// Two windows on one settings file (issue 33: "keep only one lab's settings"): each saves what it
// changed into what is on disk, so both labs, a preset of each and the camera one of them moved survive,
// in either order and over a later save of the other; what a window deletes is deleted for both.
TEST_F(SettingsTest, TwoWindowsEachKeepTheirLab) {
  Settings a = Settings::load(file), b = Settings::load(file);
  ParamSet p = params();
  p.set("shadow.bias", 0.011);
  a.store_lab(3, p);
  a.save_preset(3, "from a", p);
  p.set("shadow.bias", 0.022);
  b.store_lab(5, p);
  b.save_preset(5, "from b", p);
  b.store_camera("default", OrbitCamera{});
  a.save();
  b.save();
  p.set("shadow.bias", 0.033);
  a.store_lab(3, p);
  a.delete_preset(3, "from a");
  a.save();  // after b's save: b's lab, preset and camera stay

  const Settings both = Settings::load(file);
  EXPECT_EQ(both.warning(), "");
  ParamSet q = params();
  EXPECT_TRUE(both.apply_lab(3, q).empty());
  EXPECT_DOUBLE_EQ(q.get("shadow.bias"), 0.033);
  EXPECT_TRUE(both.apply_lab(5, q).empty());
  EXPECT_DOUBLE_EQ(q.get("shadow.bias"), 0.022) << "the other window's lab was lost";
  EXPECT_TRUE(both.preset_names(3).empty()) << "a deleted preset came back";
  EXPECT_EQ(both.preset_names(5), std::vector<std::string>{"from b"});
  EXPECT_TRUE(both.camera("default").has_value()) << "the other window's camera was lost";
  EXPECT_EQ(a.document(), both.document()) << "after saving, a window holds the merged settings";
}

// Two processes saving 50 times each, a lab and one new preset per save, side by side: the lock makes
// each read-merge-write whole, so all 100 presets and both labs' last values are on disk at the end.
TEST_F(SettingsTest, TwoProcessesSavingFiftyTimesEachLoseNothing) {
  constexpr int kSaves = 50;
  const fs::path go = dir / "go";
  const auto child = [&](int lab) {
    while (!fs::exists(go)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    Settings s = Settings::load(file);
    ParamSet p = params();
    for (int i = 0; i < kSaves; ++i) {
      p.set("shadow.bias", 0.001 * (i + 1));
      s.store_lab(lab, p);
      s.save_preset(lab, "p" + std::to_string(i), p);
      try {
        s.save();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "lab %d save %d: %s\n", lab, i, e.what());
        std::_Exit(1);
      }
    }
    std::_Exit(0);
  };
  std::vector<pid_t> children;
  for (int lab : {10, 11}) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) child(lab);
    children.push_back(pid);
  }
  write_all(go, "");
  for (pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a save failed in a child";
  }
  const Settings s = Settings::load(file);
  EXPECT_EQ(s.warning(), "");
  for (int lab : {10, 11}) {
    EXPECT_EQ(s.preset_names(lab).size(), static_cast<std::size_t>(kSaves)) << "lab " << lab << " lost presets";
    ParamSet q = params();
    EXPECT_TRUE(s.apply_lab(lab, q).empty());
    EXPECT_DOUBLE_EQ(q.get("shadow.bias"), 0.001 * kSaves) << "lab " << lab;
  }
  EXPECT_TRUE(temporaries_of(file).empty());
}

// A file that turned bad after this window loaded (another program wrote it, a disk error) is not
// written over: saving moves it aside, as loading would have, and writes this window's settings.
TEST_F(SettingsTest, FileCorruptedAfterLoadIsKeptAsideWhenSaving) {
  save_bias(0.01);
  Settings s = Settings::load(file);
  write_all(file, "{ not json");
  ParamSet p = params();
  p.set("shadow.bias", 0.02);
  s.store_lab(1, p);
  s.save();
  const std::vector<fs::path> backups = backups_of(file);
  ASSERT_EQ(backups.size(), 1u);
  EXPECT_EQ(read_all(backups[0]), "{ not json");
  EXPECT_NE(s.warning().find("is not valid JSON when saving"), std::string::npos) << s.warning();
  EXPECT_DOUBLE_EQ(loaded_bias(), 0.02);
}

// The process dies (SIGKILL) after the temporary file is written and before the rename: the temporary
// file is there, the real file is the previous one, whole, and loads; the next save goes through.
TEST_F(SettingsTest, CrashBetweenWriteAndRenameLeavesTheOldFileIntact) {
  save_bias(0.01);
  const std::string before = read_all(file);
  EXPECT_EXIT(
      {
        Settings s = Settings::load(file);
        ParamSet p = params();
        p.set("shadow.bias", 0.09);
        s.store_lab(1, p);
        s.before_rename_for_tests = [] { std::raise(SIGKILL); };
        s.save();
      },
      ::testing::KilledBySignal(SIGKILL), "");
  const std::vector<fs::path> temporaries = temporaries_of(file);
  ASSERT_EQ(temporaries.size(), 1u) << "the child got as far as writing the new file";
  EXPECT_NE(read_all(temporaries[0]).find("0.09"), std::string::npos);
  EXPECT_EQ(read_all(file), before);
  EXPECT_DOUBLE_EQ(loaded_bias(), 0.01);

  save_bias(0.03);  // the leftover temporary file does not get in the way (nor is it reused)
  EXPECT_DOUBLE_EQ(loaded_bias(), 0.03);
  EXPECT_EQ(temporaries_of(file), temporaries);
}

// Runs `body` in a child process (gtest's default "fast" death tests fork, so the child sees this
// test's files) without root's power to ignore permissions, since CI containers run tests as root; the
// child exits 0 when every check in it passed.
template <typename Body>
void expect_unprivileged(Body body) {
  EXPECT_EXIT(
      {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) std::_Exit(3);
        std::_Exit(body() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST_F(SettingsTest, UnwritableFolderGivesAClearErrorAndKeepsTheOldFile) {
  save_bias(0.01);
  const std::string before = read_all(file);
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  fs::permissions(dir / "config", fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  fs::permissions(file.parent_path(), fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_exec |
                                          fs::perms::others_exec | fs::perms::group_read | fs::perms::others_read);
  expect_unprivileged([&] {
    Settings s = Settings::load(file);
    ParamSet p = params();
    p.set("shadow.bias", 0.09);
    s.store_lab(1, p);
    try {
      s.save();
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      std::fprintf(stderr, "error: %s\n", m.c_str());
      return m.find(file.string()) != std::string::npos && m.find("Permission denied") != std::string::npos &&
             m.find('\n') == std::string::npos;
    }
    return false;
  });
  EXPECT_EQ(read_all(file), before);
  EXPECT_TRUE(temporaries_of(file).empty());

  // A bad file that cannot be moved aside is left alone, and nothing is written over it.
  write_all(file, "not json");
  expect_unprivileged([&] {
    Settings s = Settings::load(file);
    std::fprintf(stderr, "warning: %s\n", s.warning().c_str());
    if (s.warning().find("could not be moved aside") == std::string::npos) return false;
    ParamSet p = params();
    s.store_lab(1, p);
    try {
      s.save();
    } catch (const std::runtime_error&) {
      return true;
    }
    return false;
  });
  EXPECT_EQ(read_all(file), "not json");
}

TEST_F(SettingsTest, FolderThatCannotBeCreatedIsNamed) {
  write_all(dir / "config", "a file where the folder should be");
  Settings s = Settings::load(file);
  s.store_lab(1, params());
  try {
    s.save();
    FAIL() << "saved under a regular file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot create the settings folder"), std::string::npos) << e.what();
  }
}

TEST_F(SettingsTest, SymlinkedFileStaysASymlink) {
  fs::create_directories(file.parent_path());
  const fs::path real = dir / "dotfiles-settings.json";
  save_bias(0.01);
  fs::rename(file, real);
  fs::create_symlink(real, file);
  save_bias(0.04);
  EXPECT_TRUE(fs::is_symlink(file));
  EXPECT_DOUBLE_EQ(loaded_bias(), 0.04);
}

TEST(SettingsPath, EnvironmentDecidesWhere) {
  auto keep = [](const char* name) {
    const char* v = std::getenv(name);
    return std::pair<std::string, bool>(v ? v : "", v != nullptr);
  };
  const auto s = keep("SHADOWLAB_SETTINGS"), x = keep("XDG_CONFIG_HOME"), h = keep("HOME");
  ::setenv("HOME", "/home/student", 1);
  ::unsetenv("XDG_CONFIG_HOME");
  ::unsetenv("SHADOWLAB_SETTINGS");
  EXPECT_EQ(default_settings_path(), fs::path("/home/student/.config/shadowlab/settings.json"));
  ::setenv("XDG_CONFIG_HOME", "/xdg", 1);
  EXPECT_EQ(default_settings_path(), fs::path("/xdg/shadowlab/settings.json"));
  ::setenv("SHADOWLAB_SETTINGS", "/tmp/s.json", 1);
  EXPECT_EQ(default_settings_path(), fs::path("/tmp/s.json"));
  for (const auto& [name, value] : {std::pair{"SHADOWLAB_SETTINGS", s}, {"XDG_CONFIG_HOME", x}, {"HOME", h}}) {
    if (value.second) ::setenv(name, value.first.c_str(), 1);
    else ::unsetenv(name);
  }
}

}  // namespace
}  // namespace shadowlab
