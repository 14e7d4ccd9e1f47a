// One exit-code scheme for every command (the window included), printed by --help:
//   0  ok (check: every selected lab passed)
//   1  check: some lab failed (a criterion, or the student's file does not build)
//   2  usage: the command line asks for something that cannot be done as given: an unknown option, a
//      bad value, a file named on it that is missing or invalid, an output folder that cannot be written
//   3  runtime error: the tool itself failed: no OpenGL context, no window, a shader of the program
//      missing, the grader broke
#pragma once

namespace shadowlab {

constexpr int kExitOk = 0;
constexpr int kExitCheckFailed = 1;
constexpr int kExitUsage = 2;
constexpr int kExitRuntime = 3;

}  // namespace shadowlab
