// A table's recorded command line (its provenance: table_provenance.cpp in modes/app) read back as words, so that
// chain-rom can run cavity-modes again on the same cavity and mesh: served forced solves (served_response.hpp) and
// refined tables (table_refinement.hpp).
#pragma once

#include "mode_table.hpp"

#include <complex>
#include <filesystem>
#include <string>
#include <vector>

namespace rc::rom {

// The words of a command line as table_provenance.cpp's quoted_command_line writes it: blanks separate words,
// single quotes quote (a quote inside is written '\''). Throws std::runtime_error on an unclosed quote.
std::vector<std::string> shell_words(const std::string& line);

// One of cavity-modes' shape commands (sphere, spheroid, cylinder, cone, section).
bool is_shape(const std::string& word);

// A section table's file: its stored text written into `scratch` (a folder that exists), else the recorded path
// when it still exists. Throws std::runtime_error when neither.
std::filesystem::path section_file(const rc::ModeTable& table, const std::string& recorded,
                                   const std::filesystem::path& scratch);

// A number as cavity-modes reads it back, to full precision ("%.17g").
std::string number_text(double v);

// --sigma's list syntax (cavity-modes parse_sigma_spec): "re+imi" items separated by commas, full precision; what
// --exact-at takes.
std::string complex_list(const std::vector<std::complex<double>>& z);

}  // namespace rc::rom
