#include "external_programs.hpp"

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>

extern char** environ;

namespace rc::rom::app {

namespace {

// args[0] run with its standard output and error into `sink` (a file, truncated), or inherited when empty.
int spawn_and_wait(const std::vector<std::string>& args, const std::string& sink) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (!sink.empty()) {
    posix_spawn_file_actions_addopen(&fa, 1, sink.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
  }
  pid_t pid;
  const int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

int run_program(const std::vector<std::string>& args, bool quiet) {
  return spawn_and_wait(args, quiet ? "/dev/null" : "");
}

int run_program_logged(const std::vector<std::string>& args, const std::string& log_file) {
  const int status = spawn_and_wait(args, log_file);
  if (status == 0) return 0;
  // The program's last line says why (cavity-modes' errors are one line).
  std::ifstream in(log_file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  if (!last.empty()) std::fprintf(stderr, "%s\n", last.c_str());
  return status;
}

std::string plot_python() {
  const char* env = std::getenv("CHAIN_ROM_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

void check_plot_tools(const std::string& script, const std::string& what) {
  if (!std::filesystem::exists(script))
    throw std::runtime_error("--png: " + script + " not found (the source tree's scripts/)");
  if (run_program({plot_python(), "-c", "import matplotlib, numpy"}, true) != 0)
    throw std::runtime_error("--png: " + plot_python() + " with matplotlib and numpy is needed to draw the " + what +
                             " (apt-get install python3-matplotlib); nothing written");
}

void draw_plot(const std::string& script, const std::string& csv, const std::string& png,
               const std::vector<std::string>& extra) {
  std::vector<std::string> cmd = {plot_python(), script, csv, "-o", png};
  cmd.insert(cmd.end(), extra.begin(), extra.end());
  const int rc = run_program(cmd);
  if (rc != 0)
    throw std::runtime_error("--png: " + script + " failed (exit " + std::to_string(rc) + "); the CSV " + csv +
                             " was written, no PNG");
  std::printf("wrote %s\n", png.c_str());
}

}  // namespace rc::rom::app
