// chain-rom's subcommands, one file each: `add_*` registers a subcommand's options on the app and returns the
// function that runs it once the command line is parsed (a command's request is resolved there, once). The run
// function throws std::exception with a one-line cause (main prints it, exit 1) or returns the exit code.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace rc::rom::app {

struct Command {
  CLI::App* cli = nullptr;
  std::function<int()> run;
};

Command add_spectrum_command(CLI::App& app);  // spectrum_cli.cpp
Command add_confirm_command(CLI::App& app);   // spectrum_cli.cpp
Command add_run_command(CLI::App& app);       // run_cli.cpp
Command add_sweep_command(CLI::App& app);     // sweep_cli.cpp
Command add_bench_command(CLI::App& app);     // bench_cli.cpp
Command add_response_command(CLI::App& app);  // response_cli.cpp

}  // namespace rc::rom::app
