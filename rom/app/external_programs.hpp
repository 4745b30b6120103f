// The plot scripts that `sweep --png` and `bench --png` run (Debian's /usr/bin/python3 with matplotlib).
#pragma once

#include <string>
#include <vector>

namespace rc::rom::app {

// Runs args[0] with the arguments (no shell); returns its exit status, or -1 if it cannot start.
int run_program(const std::vector<std::string>& args, bool quiet = false);

// The same with its output into `log_file`; when it fails, its last line is printed on standard error.
int run_program_logged(const std::vector<std::string>& args, const std::string& log_file);

// The Python that draws maps: Debian's (python3-matplotlib), or $CHAIN_ROM_PYTHON.
std::string plot_python();

// Before the work: throws a one-line error when `script` or a Python with matplotlib and numpy is missing.
void check_plot_tools(const std::string& script, const std::string& what);

// Draws `png` from `csv` with `script` (and `extra` arguments); throws a one-line error naming the written CSV when
// the script fails. Prints "wrote PNG".
void draw_plot(const std::string& script, const std::string& csv, const std::string& png,
               const std::vector<std::string>& extra = {});

}  // namespace rc::rom::app
