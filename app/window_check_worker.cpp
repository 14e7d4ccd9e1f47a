// The window's contexts: create_window, and the Check's worker thread with a hidden window of its own.
#include "app/window_app.h"

#include "renderer/gl.h"  // before GLFW, so GLFW does not include a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "renderer/context.h"

namespace shadowlab {

GLFWwindow* create_window(bool visible, int width, int height) {
  const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
  for (const auto& v : versions) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#ifndef NDEBUG
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
    if (GLFWwindow* w = glfwCreateWindow(visible ? width : 1, visible ? height : 1, "shadowlab", nullptr, nullptr)) {
      take_glfw_error();  // the versions refused before this one are not an error
      return w;
    }
  }
  return nullptr;
}

CheckWorker::~CheckWorker() {
  if (thread_.joinable()) thread_.join();
  if (context_) glfwDestroyWindow(context_);
}

double CheckWorker::seconds() const { return glfwGetTime() - started_; }

bool CheckWorker::start(const Lab& lab, Impl impl, const Scene& scene, bool foreign_scene, std::string* error) {
  if (running()) return false;
  if (!context_) {
    GLFWwindow* current = glfwGetCurrentContext();
    context_ = create_window(false);
    glfwMakeContextCurrent(current);
    if (!context_) {
      *error = "cannot create a context for the Check: " + take_glfw_error();
      return false;
    }
  }
  lab_ = &lab;
  impl_ = impl;
  done_ = false;
  started_ = glfwGetTime();
  thread_ = std::thread([this, scene, foreign_scene] {
    glfwMakeContextCurrent(context_);
    try {
      result_ = run_lab_check(*lab_, impl_, scene, foreign_scene);
    } catch (const std::exception& e) {
      CheckResult r;
      r.lab = lab_->number;
      r.error = e.what();
      result_ = std::move(r);
    }
    glFinish();
    glfwMakeContextCurrent(nullptr);
    done_ = true;
  });
  return true;
}

std::optional<CheckResult> CheckWorker::take_result() {
  if (!running() || !done_) return std::nullopt;
  thread_.join();
  return std::move(result_);
}

}  // namespace shadowlab
