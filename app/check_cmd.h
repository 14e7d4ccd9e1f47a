// `shadowlab check`: grade labs headless against the oracle; exit 0 only if every selected check passes.
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct CheckOptions {
  std::string labs = "all";  // "all", "1" or "3,4,5"
  std::string impl = "solution";
  std::string scene_file;
  std::string json_file;
  std::string out_dir;
  std::string submission;  // a student's folder: its exercise files are graded
  std::vector<std::string> assignments;  // --set key=value, applied over each lab's defaults
};

int run_check(const CheckOptions& options);

// Parses "all" or a comma-separated list of lab numbers; throws with the valid numbers on error.
std::vector<int> parse_lab_list(const std::string& text);

}  // namespace shadowlab
