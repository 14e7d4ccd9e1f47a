// Scripted input for tests and documentation: `--script "key:2,frames:3,screenshot:a.png,key:s"`.
// Key presses go through ImGui's GLFW key callback, the handler a real key press reaches, so a test
// exercises the same path a person's keyboard does. Steps, in order, one per comma:
//   key:K          press and release K (a digit, a letter, f1..f12, left, right, escape, pagedown, pageup)
//   click:X;Y      move the mouse to pixel (X, Y) of the window (0;0 its top left) and click the left button
//                  there (pressed one frame, released the next), through ImGui's GLFW mouse callbacks
//   frames:N       let N frames pass
//   screenshot:F   save the next drawn frame, panel included, to F
//   resize:WxH     set the window's size
//   iconify / restore   minimise the window / bring it back
//   wait:S         let S seconds pass (a minimised window draws no frames)
//   drop:F         drop file F on the window (through the window's drop callback)
//   check          press the panel's Check button (the same request the button makes)
//   solution-beside  press the panel's "Solution beside it" button (the same request)
// When the script ends the window closes.
#pragma once

#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace shadowlab {

class InputScript {
 public:
  // Throws std::invalid_argument naming the bad step.
  explicit InputScript(const std::string& text);
  bool empty() const { return steps_.empty(); }

  // Call once per loop turn before events are polled. Returns a screenshot path when the next drawn
  // frame should be saved (else empty).
  std::string advance(GLFWwindow* window, double now);
  // Call after each drawn frame.
  void frame_drawn() { ++frames_drawn_; }
  bool finished() const {
    return next_ >= steps_.size() && pending_release_ < 0 && !pending_click_release_ && frames_drawn_ >= wait_until_frame_;
  }
  // True once after a `check` step.
  bool take_check_request() { return std::exchange(check_requested_, false); }
  // True once after a `solution-beside` step.
  bool take_solution_beside_request() { return std::exchange(solution_beside_requested_, false); }

 private:
  struct Step {
    std::string kind, arg;
    int a = 0, b = 0;
  };
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  int pending_release_ = -1;  // a key pressed last turn, released this turn (ImGui 1.86 reads key state)
  bool pending_click_release_ = false;  // the left button pressed last turn, released this turn
  long frames_drawn_ = 0;
  long wait_until_frame_ = 0;
  double wait_until_time_ = 0.0;
  bool check_requested_ = false;
  bool solution_beside_requested_ = false;
};

// GLFW key code for a script's key name; -1 if unknown.
int key_code(const std::string& name);

}  // namespace shadowlab
