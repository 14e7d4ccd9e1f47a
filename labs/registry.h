// The lab registry: every lab folder's lab (labs/NN_slug), found by its number, its slug or what it offers
// the bench. What a lab is (its parameters, files, hooks and check) is grading/lab.h; this is which labs
// there are, so only the labs and what stands above them (the app, the bench) can ask it.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "grading/lab.h"

namespace shadowlab {

// Every lab, in number order: one per folder labs/NN_slug (labs/CMakeLists.txt generates the list).
// A folder's lab.cpp defines `Lab SHADOWLAB_LAB_MAKER()` and names its own files under
// SHADOWLAB_LAB_FOLDER; the number and slug come from the folder's name.
const std::vector<Lab>& all_labs();
// The lab the user asked for by its number (--lab N, the number keys, a submission's lab). Code that needs
// what a lab offers finds it by that instead (below): numbers follow the course's order and change with it.
const Lab* find_lab(int number);
// The lab of this slug (its folder's name without the number: "pcf"); the lowest-numbered one when a
// copied folder kept its slug. Null when none.
const Lab* find_lab_named(std::string_view slug);
// The lab that offers this technique to `shadowlab bench` (a BenchTechnique's name: "hard", "pcf 3");
// the lowest-numbered one when several do. Null when none.
const Lab* find_lab_offering(std::string_view bench_technique);
// Generated from the folders (build/labs/lab_list.cpp): each folder's lab, numbered by folder_lab.
std::vector<Lab> folder_labs();
Lab folder_lab(Lab lab, int number, std::string slug);
// Generated at build time (build/labs/compiled_exercises.cpp, by cmake/embed_exercises.cmake): every
// lab's C++ exercise file (labs/NN_slug/exercise.cpp) as it was when this program was built, by its path
// relative to the project. folder_lab hands each lab its own (Lab::compiled_copies).
const std::map<std::string, std::string_view>& compiled_exercises();

}  // namespace shadowlab
