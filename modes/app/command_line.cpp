#include "command_line.hpp"

#include <cctype>

namespace rc::modes {

SplitArguments split_arguments(int argc, char** argv) {
  SplitArguments s;
  s.ours.push_back(argv[0]);
  s.petsc.push_back(argv[0]);
  auto is_petsc_option = [](const std::string& a) {
    // "-pep_type" or "-log_view": one dash, then a letter, and longer than a short option like "-o".
    return a.size() > 2 && a[0] == '-' && std::isalpha(static_cast<unsigned char>(a[1]));
  };
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (!is_petsc_option(a)) { s.ours.push_back(a); continue; }
    s.petsc.push_back(a);
    // A following token that is not an option is the PETSc option's value.
    if (i + 1 < argc && argv[i + 1][0] != '-') s.petsc.push_back(argv[++i]);
  }
  return s;
}

}  // namespace rc::modes
