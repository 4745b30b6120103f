// Splits a command line into PETSc/SLEPc options (single dash and a name: -pep_type stoar, -log_view)
// and our own (CLI11: --order 4, -o FILE), so that PETSc options pass straight through.
#pragma once

#include <string>
#include <vector>

namespace rc::modes {

struct SplitArguments {
  std::vector<std::string> ours;   // argv[0] first
  std::vector<std::string> petsc;  // argv[0] first
};

SplitArguments split_arguments(int argc, char** argv);

}  // namespace rc::modes
