// Output files written through a temporary name beside them and renamed into place once complete: a reader never
// sees a half-written file, and a failure leaves nothing behind (the tables, CSVs and histories of both programs).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rc {

// write(tmp) makes the file at the temporary path tmp; then it becomes `out`. Throws std::runtime_error when the
// folder does not exist, and passes on whatever write throws (the temporary file removed).
template <class Writer>
void write_file_atomically(const std::filesystem::path& out, Writer write) {
  namespace fs = std::filesystem;
  if (out.has_parent_path() && !fs::is_directory(out.parent_path()))
    throw std::runtime_error(out.string() + ": the output folder does not exist");
  fs::path tmp = out;
  tmp += ".tmp-" + std::to_string(::getpid());
  try {
    write(tmp);
    fs::rename(tmp, out);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

// The same for a text file: write(os) fills the stream; a stream that fails is an error.
template <class Writer>
void write_text_atomically(const std::filesystem::path& out, Writer write) {
  write_file_atomically(out, [&](const std::filesystem::path& tmp) {
    std::ofstream os(tmp);
    if (!os) throw std::runtime_error(tmp.string() + ": cannot create");
    write(os);
    os.flush();
    if (!os) throw std::runtime_error(tmp.string() + ": write failed");
  });
}

}  // namespace rc
