// The forced solves of a response table kept on disk as they are made (FILE.h5.samples beside the table), so that a
// fit that misses its tolerance, or a run that is stopped, loses none of them: the same command, or one with a larger
// --max-fit-error or more frequencies, reads them back and solves only the frequencies it has not got
// (docs/viscous.md, "Response fit"). The file is removed once the table is written.
//
// Text, one line a sample "sigma_re sigma_im R_re R_im" (17 digits) after a first line "# key: ..." that names the
// cavity, its mesh, the Ekman number and the unknowns: samples are reused only for the same key. Rank 0 reads and
// writes it; under mpirun the other ranks get the samples from it (MPI_Bcast).
#pragma once

#include "meridian_mesh.hpp"

#include <complex>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

namespace rc::modes {

// The key of a cavity's samples: shape, dimensions (a section's text by its hash), mesh options, Ek, unknowns.
std::string response_samples_key(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, double ekman,
                                 long unknowns);

class ResponseSamples {
 public:
  ResponseSamples() = default;  // keeps nothing (no file)
  // Reads `path` when it exists with this key (a file with another key is replaced on the first add).
  ResponseSamples(std::filesystem::path path, std::string key);
  bool find(std::complex<double> sigma, std::complex<double>& R) const;
  void add(std::complex<double> sigma, std::complex<double> R);  // appended and flushed at once (rank 0)
  std::size_t read() const { return read_; }    // samples found in the file when it was opened
  std::size_t added() const { return added_; }  // samples added since
  const std::filesystem::path& path() const { return path_; }
  void remove();                              // the table is written: the samples are no longer needed

 private:
  std::filesystem::path path_;
  std::string key_;
  std::map<std::pair<double, double>, std::complex<double>> samples_;
  std::size_t read_ = 0, added_ = 0;
  bool fresh_ = true;  // the file must be (re)started with the key line before the first add
};

}  // namespace rc::modes
