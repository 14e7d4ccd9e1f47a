// `shadowlab check`: grade labs headless against the oracle; exit 0 only if every selected check passes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

struct CheckOptions {
  std::string labs = "all";  // "all", "1" or "3,4,5"
  std::string impl = "exercise";  // the student's file(s); "solution" grades the lab's own
  std::string submission;  // a folder laid out like the project whose exercise files are graded instead
  std::uint32_t seed = 1;  // held-out conditions
  std::string scene_file;
  std::string json_file;
  std::string out_dir;
  std::string preset;                    // --preset NAME: each lab's preset of that name, over its defaults
  std::vector<std::string> assignments;  // --set key=value, applied over each lab's defaults (and the preset)
};

// Exit codes: 0 every lab passed, 1 some lab failed (a criterion, or the student's file does not
// build), 2 usage error, 3 grader error (the grader itself broke: its own shader, a missing asset, no
// GL context), which takes precedence.
int run_check(const CheckOptions& options);

// Parses "all" or a comma-separated list of lab numbers; throws with the valid numbers on error.
std::vector<int> parse_lab_list(const std::string& text);

}  // namespace shadowlab
