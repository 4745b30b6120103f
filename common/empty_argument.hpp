// Both programs' guard against empty option values: CLI11 takes "--coverage ''" or "--from=" as no value at all,
// and the option would silently keep its default (found by the fuzz test, tests/fuzz/fuzz_test.py).
#pragma once

#include <string>

namespace rc {

// The one-line cause for the first empty argument (or "--name=" with nothing after it), or "" if there is none.
inline std::string empty_argument_error(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (!a.empty() && !(a.rfind("--", 0) == 0 && a.back() == '=')) continue;
    const std::string where = !a.empty() ? " for " + a.substr(0, a.size() - 1)
                              : i > 1    ? " after " + std::string(argv[i - 1])
                                         : std::string();
    return "an empty value" + where + ": give a value or leave the option out";
  }
  return {};
}

}  // namespace rc
