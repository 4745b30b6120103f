#include "recorded_command.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace rc::rom {
namespace fs = std::filesystem;

std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string w;
  bool in_word = false, quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '\'') quoted = false;
      else w += c;
    } else if (c == '\'') {
      quoted = in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      w += line[++i];
      in_word = true;
    } else if (c == ' ' || c == '\t' || c == '\n') {
      if (in_word) words.push_back(w);
      w.clear();
      in_word = false;
    } else {
      w += c;
      in_word = true;
    }
  }
  if (quoted) throw std::runtime_error("its recorded command line has an unclosed quote");
  if (in_word) words.push_back(w);
  return words;
}

bool is_shape(const std::string& w) {
  for (const char* k : {"sphere", "spheroid", "cylinder", "cone", "section"})
    if (w == k) return true;
  return false;
}

fs::path section_file(const rc::ModeTable& t, const std::string& recorded, const fs::path& scratch) {
  const bool text = !t.geometry_text.empty() && t.geometry_text.rfind("(binary file", 0) != 0;
  if (!text) {
    if (fs::exists(recorded)) return recorded;
    throw std::runtime_error("its section file " + recorded + " is not stored in it and not found");
  }
  const fs::path file = scratch / ("section" + fs::path(recorded).extension().string());
  std::ofstream(file, std::ios::binary) << t.geometry_text;
  return file;
}

std::string number_text(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string complex_list(const std::vector<std::complex<double>>& z) {
  std::string out;
  char item[96];
  for (const std::complex<double>& s : z) {
    std::snprintf(item, sizeof item, "%s%.17g%+.17gi", out.empty() ? "" : ",", s.real(), s.imag());
    out += item;
  }
  return out;
}

}  // namespace rc::rom
