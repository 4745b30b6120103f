// chain-rom: characteristic roots and time histories of a chain of spinning bodies with fluid-filled cavities
// (docs/physics.md §3-4). One subcommand a file (commands.hpp); one-line error and exit code 1 on bad input, 2 on a
// command-line error, 3 when confirm leaves a root not confirmed (docs/rom.md).
#include "commands.hpp"
#include "empty_argument.hpp"

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"chain-rom: stability and motion of a chain of n spinning bodies with fluid-filled "
               "cavities (reads mode tables written by cavity-modes; scene format: docs/scene-format.md)"};
  app.require_subcommand(1);
  using namespace rc::rom::app;
  const std::vector<Command> commands = {add_spectrum_command(app), add_confirm_command(app), add_run_command(app),
                                         add_sweep_command(app), add_bench_command(app), add_response_command(app)};
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    std::string msg = e.what();
    for (auto& ch : msg) if (ch == '\n') ch = ' ';
    return "chain-rom: error: " + msg + " (--help for usage)\n";
  });
  if (const std::string empty = rc::empty_argument_error(argc, argv); !empty.empty()) {
    std::fprintf(stderr, "chain-rom: error: %s\n", empty.c_str());  // a command-line error: exit 2
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help: 0; every command-line error: 2, whatever CLI11's own code (docs/rom.md).
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    for (const Command& c : commands)
      if (c.cli->parsed()) return c.run();
  } catch (const std::exception& e) {
    std::string msg = e.what();
    for (auto& ch : msg) if (ch == '\n') ch = ' ';
    std::cerr << "chain-rom: error: " << msg << "\n";
    return 1;
  }
  return 0;
}
