#include "app/command_options.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/gltf_loader.h"
#include "core/platform.h"
#include "core/untrusted.h"
#include "grading/lab.h"

namespace shadowlab {

namespace fs = std::filesystem;

Scene load_scene_or_default(const std::string& path) {
  if (path.empty()) return make_default_scene();
  std::vector<std::string> warnings;
  Scene scene = load_gltf(path, {}, &warnings);
  for (const std::string& w : warnings)
    std::fprintf(stderr, "shadowlab: warning: %s: %s\n", printable(path, 400).c_str(), printable(w, 400).c_str());
  return scene;
}

std::string one_line_error(const std::string& message) {
  std::string m = message;
  while (!m.empty() && m.back() == '\n') m.pop_back();
  const auto nl = m.find('\n');
  if (nl == std::string::npos || m.find('\n', nl + 1) != std::string::npos) return m;
  return m.substr(0, nl) + " " + m.substr(nl + 1);
}

void prove_writable_folder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error(dir + ": cannot create the output folder" + (ec ? ": " + ec.message() : std::string()));
  try {
    platform::probe_writable(dir);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(dir + ": the output folder is not writable: " + e.what());
  }
}

void make_output_dir(const std::string& dir) {
  prove_writable_folder(dir);
  std::string holder;
  bool locked = false;
  try {
    locked = platform::lock_folder(dir, &holder);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(dir + ": cannot lock the output folder: " + e.what());
  }
  if (!locked)
    throw std::runtime_error(dir + ": the output folder is in use by another shadowlab run" +
                             (holder.empty() ? std::string() : " (process " + holder + ")") +
                             "; wait for it to finish or choose another --out");
}

void apply_set_option(ParamSet& params, const std::string& assignment) {
  try {
    params.apply_assignment(assignment);
  } catch (const std::exception& e) {
    throw std::invalid_argument("--set " + assignment + ": " + e.what());
  }
}

const Preset* apply_preset_option(ParamSet& params, const Lab& lab, const std::string& name) {
  if (name.empty()) return nullptr;
  try {
    const Preset& preset = find_preset(lab, name);
    apply_preset(params, preset);
    return &preset;
  } catch (const std::exception& e) {
    throw std::invalid_argument("--preset " + name + ": " + e.what());
  }
}

Scene scene_option(const std::string& scene_file, const Preset* preset) {
  if (!scene_file.empty() || !preset || preset->view.scene.empty()) return load_scene_or_default(scene_file);
  try {
    return builtin_scene(preset->view.scene);
  } catch (const std::exception& e) {
    throw std::invalid_argument("--preset " + preset->name + ": " + e.what());
  }
}

OrbitCamera camera_option(const std::string& spec, const Bounds& bounds) {
  const OrbitCamera framed = OrbitCamera::framing(bounds);
  if (spec.empty()) return framed;
  glm::vec3 eye = framed.eye(), target = framed.target;
  float fov = framed.fov_y_deg;
  std::istringstream words(spec);
  std::string word;
  auto bad = [&](const std::string& why) { return std::invalid_argument("--camera " + spec + ": " + word + ": " + why); };
  auto number = [&](const std::string& text) {
    std::size_t used = 0;
    float v = 0.0f;
    try {
      v = std::stof(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || !std::isfinite(v)) throw bad("'" + text + "' is not a number");
    return v;
  };
  while (words >> word) {
    const auto eq = word.find('=');
    const std::string key = word.substr(0, eq), value = eq == std::string::npos ? "" : word.substr(eq + 1);
    if (key == "eye" || key == "target") {
      glm::vec3 v{0.0f};
      std::istringstream parts(value);
      std::string part;
      int n = 0;
      while (std::getline(parts, part, ',')) {
        if (n == 3) throw bad("three numbers expected, x,y,z");
        v[n++] = number(part);
      }
      if (n != 3) throw bad("three numbers expected, x,y,z");
      (key == "eye" ? eye : target) = v;
    } else if (key == "fov") {
      fov = number(value);
      if (fov < 1.0f || fov > 170.0f) throw bad("the field of view is 1-170 degrees");
    } else {
      throw bad("expected eye=x,y,z, target=x,y,z or fov=deg");
    }
  }
  word = "eye, target";
  if (glm::length(eye - target) < 1e-6f) throw bad("the eye and the target are the same point");
  return OrbitCamera::looking(eye, target, fov, bounds);
}

OrbitCamera view_camera(const std::string& camera_spec, const Preset* preset, const Scene& scene, const ParamSet& params) {
  if (!camera_spec.empty()) return camera_option(camera_spec, frame_scene_bounds(scene, params));
  if (!preset || preset->view.camera.empty()) return frame_scene_camera(scene, params);
  try {
    return camera_option(preset->view.camera, frame_scene_bounds(scene, params));
  } catch (const std::exception& e) {
    throw std::invalid_argument("--preset " + preset->name + ": " + e.what());
  }
}

void parse_size_option(const std::string& spec, int* width, int* height) {
  const auto x = spec.find('x');
  std::size_t used_w = 0, used_h = 0;
  int w = 0, h = 0;
  try {
    if (x != std::string::npos) {
      w = std::stoi(spec.substr(0, x), &used_w);
      h = std::stoi(spec.substr(x + 1), &used_h);
    }
  } catch (const std::exception&) {
    w = h = 0;
  }
  if (x == std::string::npos || used_w != x || used_h != spec.size() - x - 1 || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw std::invalid_argument("--size " + spec + ": expected WxH, each 16-8192 pixels (e.g. 1280x720)");
  *width = w;
  *height = h;
}

}  // namespace shadowlab
