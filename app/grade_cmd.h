// `shadowlab grade`: a whole class, one command. Each submission's labs are graded one by one, each in
// its own `shadowlab check --submission` process under a wall-clock and a memory limit; each lab's
// result is written as soon as it is known (students/<name>/lab_NN.json), so a run that is killed
// loses nothing graded and a rerun continues where it stopped. Several submissions at once go through
// GNU parallel (--jobs), or through a Slurm job array (scripts/slurm/); the merge step then writes the
// class's reports (app/grade_report.h).
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

struct GradeOptions {
  std::vector<std::string> submissions;  // folders or zip/tar archives
  std::string out_dir;
  std::string labs = "all";
  int jobs = 1;               // > 1: that many submissions at once, through GNU parallel
  double cpu_time = 60.0;     // CPU seconds per lab (a C++ lab's compile included): the same verdict whatever the load
  double timeout = 300.0;     // wall-clock seconds per lab: the backstop for what does not use CPU
  int memory_mb = 2048;       // address space per lab's process
  std::string images = "failed";  // diff images kept: none, failed (labs not passed), all
  bool merge_only = false;    // --merge: write the reports from what is in out_dir
  bool no_merge = false;      // --no-merge: grade only (one task of a parallel or Slurm run)
  bool again = false;         // --again: grade every lab again, even those already recorded
};

// Exit codes: 0 every lab of every submission passed; 1 some did not (the students' work); 2 usage;
// 3 a grader error (the grader itself failed somewhere: look at the report before using it).
int run_grade(const GradeOptions& options);

}  // namespace shadowlab
