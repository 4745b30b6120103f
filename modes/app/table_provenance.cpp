#include "table_provenance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace rc::modes {

std::string quoted_command_line(const std::vector<std::string>& argv) {
  std::string line;
  for (const auto& a : argv) {
    if (!line.empty()) line += ' ';
    const bool plain = !a.empty() && a.find_first_of(" \t\n'\"\\$`*?;&|<>()") == std::string::npos;
    if (plain) { line += a; continue; }
    line += '\'';
    for (char c : a) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

void record_provenance(ModeTable& table, const geometry::ShapeSpec& shape, const std::string& command_line) {
  table.command_line = command_line;
  if (shape.kind != "section") {
    table.geometry_source = shape.kind;
    for (const auto& [name, value] : shape.dims) table.geometry_source += fmt::format(" {}={:.17g}", name, value);
    table.geometry_text.clear();
    return;
  }
  table.geometry_source = shape.file.string();
  std::ifstream in(shape.file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  // A binary .msh holds NUL bytes: HDF5's C strings would cut it, so it is described instead of stored.
  table.geometry_text = s.find('\0') == std::string::npos
                            ? s : fmt::format("(binary file of {} bytes, not stored)", s.size());
}

}  // namespace rc::modes
