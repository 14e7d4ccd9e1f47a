// The hostile models of issue 18, made in code (several are tens of megabytes, or FIFOs and sparse
// files, so they are never stored): each with what its refusal must say. test_core loads every one
// (under ASan+UBSan in scripts/test); the hostile_cases tool writes them for the command-line test,
// which runs `shadowlab render --scene` on each and holds it to 10 s and 1 GB.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::test {

struct HostileCase {
  std::string name;          // e.g. "deep_extras"
  std::filesystem::path file;
  std::string must_mention;  // a fragment of the refusal
  std::string issue_item;    // which finding of issue 18 it reproduces
};

// Writes every case under `dir` (created) and returns them, in a fixed order.
std::vector<HostileCase> write_hostile_cases(const std::filesystem::path& dir);

}  // namespace shadowlab::test
