// A viscous tank's own response R(s), by forced solves of the Navier–Stokes problem on the mesh its table was made on:
// chain-rom starts `cavity-modes response SHAPE ... --ekman Ek --serve` (docs/viscous.md, "Response function") as a
// child process, writes one complex s a line to it and reads R(s) back. The shape and mesh options come from the
// table's own provenance (its recorded command line and, for a section, the section text it stores), so any table
// cavity-modes made can be checked against the fluid it stands for (docs/rom.md, "Confirmed roots").
#pragma once

#include "mode_table.hpp"

#include <array>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace rc::rom {

// The mesh of a tank's served forced solves: its table's own, or a mesh study's — the table's with --mesh-size and
// --order replaced where given, then every size halved `level` times (cavity-modes response --mesh-level).
struct ServedMesh {
  int level = 0;
  double mesh_size = 0;  // > 0: in place of the table's --mesh-size
  int order = 0;         // > 0: in place of the table's --order
  int order_raise = 0;   // the order (the table's or `order`) raised by this much: a study in the order (at most 6)
  bool is_tables() const { return level == 0 && mesh_size == 0 && order == 0 && order_raise == 0; }
};

// The arguments after the program's name of `cavity-modes response ... --serve` for a viscous table: the shape and
// its dimensions, --order, --mesh-size, --radial-size, --wall-size from the table's command line, --ekman from the
// table (or `ekman` when positive: the same cavity and mesh at another Ekman number, for sweeps over spin). A
// section's file is written from the table's stored text into `scratch` (a folder that must exist). Throws
// std::runtime_error with one line when the table is not viscous or its command line cannot be read back.
// `mesh_ekman` (when positive) makes the mesh as for that Ekman number (cavity-modes --mesh-ekman): one mesh for
// every point of a sweep over spin, its wall layers those of the sweep's smallest Ek.
// `mesh` (when not the table's) changes the mesh for a mesh study (docs/rom.md, "Mesh error of confirmed roots").
struct ServedMesh;
std::vector<std::string> serve_arguments(const rc::ModeTable& table, const std::filesystem::path& scratch,
                                         double ekman, double mesh_ekman, const ServedMesh& mesh);
std::vector<std::string> serve_arguments(const rc::ModeTable& table, const std::filesystem::path& scratch,
                                         double ekman = 0, double mesh_ekman = 0);

// The cavity-modes binary: `given` if not empty, else $CAVITY_MODES, else ../modes/cavity-modes beside this
// executable (the build tree), else "cavity-modes" (searched on PATH).
std::string cavity_modes_binary(const std::string& given);

class ServedResponse {
 public:
  // Starts the child and waits for its "ready:" line (the mesh is assembled by then). Throws std::runtime_error with
  // the child's own error line when it does not start.
  ServedResponse(const std::string& binary, const std::vector<std::string>& args);
  ~ServedResponse();
  ServedResponse(const ServedResponse&) = delete;
  ServedResponse& operator=(const ServedResponse&) = delete;

  std::complex<double> operator()(std::complex<double> s);  // throws std::runtime_error with the child's reason
  // A partially filled tank's child (served with --fill): R, R_fg, R_gg at s.
  std::array<std::complex<double>, 3> offset(std::complex<double> s);
  const std::string& ready_line() const { return ready_; }  // "viscous fluid, Ekman number ..., N real unknowns)"
  long unknowns() const;                                    // from the ready line; 0 if it names none
  int solves() const { return solves_; }

 private:
  std::string read_line();
  std::vector<double> ask(std::complex<double> s, int count);  // one line of `count` numbers back
  void shut();                      // closes the pipes, waits for the child, removes the message file
  std::string child_error() const;  // the last line the child wrote on stderr
  pid_t pid_ = -1;
  std::FILE* to_child_ = nullptr;
  std::FILE* from_child_ = nullptr;
  std::filesystem::path stderr_file_;
  std::string ready_;
  int solves_ = 0;
};

}  // namespace rc::rom
