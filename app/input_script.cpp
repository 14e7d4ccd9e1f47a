#include "app/input_script.h"

#include <cctype>
#include <sstream>
#include <stdexcept>

#include "renderer/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

namespace shadowlab {

int key_code(const std::string& name) {
  if (name.size() == 1) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
  }
  if ((name[0] == 'f' || name[0] == 'F') && name.size() <= 3 && std::isdigit(static_cast<unsigned char>(name.back()))) {
    const int n = std::stoi(name.substr(1));
    if (n >= 1 && n <= 12) return GLFW_KEY_F1 + n - 1;
  }
  if (name == "left") return GLFW_KEY_LEFT;
  if (name == "right") return GLFW_KEY_RIGHT;
  if (name == "escape") return GLFW_KEY_ESCAPE;
  if (name == "pagedown") return GLFW_KEY_PAGE_DOWN;
  if (name == "pageup") return GLFW_KEY_PAGE_UP;
  return -1;
}

InputScript::InputScript(const std::string& text) {
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    Step s;
    const auto colon = item.find(':');
    s.kind = item.substr(0, colon);
    s.arg = colon == std::string::npos ? "" : item.substr(colon + 1);
    const auto bad = [&] { return std::invalid_argument("--script: bad step '" + item + "'"); };
    try {
      if (s.kind == "key") {
        s.a = key_code(s.arg);
        if (s.a < 0) throw bad();
      } else if (s.kind == "frames") {
        s.a = std::stoi(s.arg);
      } else if (s.kind == "wait") {
        s.a = static_cast<int>(std::stod(s.arg) * 1000.0);
      } else if (s.kind == "click") {
        const auto semicolon = s.arg.find(';');
        if (semicolon == std::string::npos) throw bad();
        s.a = std::stoi(s.arg.substr(0, semicolon));
        s.b = std::stoi(s.arg.substr(semicolon + 1));
        if (s.a < 0 || s.b < 0) throw bad();
      } else if (s.kind == "resize") {
        const auto x = s.arg.find('x');
        s.a = std::stoi(s.arg.substr(0, x));
        s.b = std::stoi(s.arg.substr(x + 1));
        if (s.a < 1 || s.b < 1) throw bad();
      } else if (s.kind == "screenshot" || s.kind == "drop") {
        if (s.arg.empty()) throw bad();
      } else if (s.kind != "iconify" && s.kind != "restore" && s.kind != "check" &&
                 s.kind != "solution-beside") {
        throw bad();
      }
    } catch (const std::invalid_argument&) {
      throw bad();
    } catch (const std::out_of_range&) {
      throw bad();
    }
    steps_.push_back(s);
  }
}

std::string InputScript::advance(GLFWwindow* window, double now) {
  if (pending_release_ >= 0) {
    ImGui_ImplGlfw_KeyCallback(window, pending_release_, 0, GLFW_RELEASE, 0);
    pending_release_ = -1;
    wait_until_frame_ = frames_drawn_ + 1;  // let a frame see the release before the next press
    return {};
  }
  if (pending_click_release_) {
    ImGui_ImplGlfw_MouseButtonCallback(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
    pending_click_release_ = false;
    wait_until_frame_ = frames_drawn_ + 1;
    return {};
  }
  std::string screenshot;
  while (next_ < steps_.size() && frames_drawn_ >= wait_until_frame_ && now >= wait_until_time_) {
    const Step& s = steps_[next_++];
    if (s.kind == "key") {
      ImGui_ImplGlfw_KeyCallback(window, s.a, glfwGetKeyScancode(s.a), GLFW_PRESS, 0);
      pending_release_ = s.a;
      wait_until_frame_ = frames_drawn_ + 1;  // the next drawn frame sees it pressed
    } else if (s.kind == "click") {
      // The pointer moved as a person's mouse would move it; ImGui 1.86's backend reads its position
      // from GLFW once it knows the pointer is over the window, later ones take it from the callback.
      glfwSetCursorPos(window, s.a, s.b);
      ImGui_ImplGlfw_CursorEnterCallback(window, GLFW_TRUE);
#if IMGUI_VERSION_NUM >= 18700
      ImGui_ImplGlfw_CursorPosCallback(window, s.a, s.b);
#endif
      ImGui_ImplGlfw_MouseButtonCallback(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
      pending_click_release_ = true;
      wait_until_frame_ = frames_drawn_ + 1;  // the next drawn frame sees it pressed
    } else if (s.kind == "frames") {
      wait_until_frame_ = frames_drawn_ + s.a;
    } else if (s.kind == "wait") {
      wait_until_time_ = now + s.a / 1000.0;
    } else if (s.kind == "screenshot") {
      screenshot = s.arg;
      wait_until_frame_ = frames_drawn_ + 1;
    } else if (s.kind == "resize") {
      glfwSetWindowSize(window, s.a, s.b);
      wait_until_frame_ = frames_drawn_ + 1;
    } else if (s.kind == "drop") {
      // The callback the window installed, as a real drop would call it.
      const GLFWdropfun callback = glfwSetDropCallback(window, nullptr);
      glfwSetDropCallback(window, callback);
      const char* path = s.arg.c_str();
      if (callback) callback(window, 1, &path);
      wait_until_frame_ = frames_drawn_ + 1;
    } else if (s.kind == "iconify") {
      glfwIconifyWindow(window);
    } else if (s.kind == "restore") {
      glfwRestoreWindow(window);
    } else if (s.kind == "check") {
      check_requested_ = true;
    } else if (s.kind == "solution-beside") {
      solution_beside_requested_ = true;
      wait_until_frame_ = frames_drawn_ + 1;
    }
    if (!screenshot.empty()) break;
  }
  return screenshot;
}

}  // namespace shadowlab
