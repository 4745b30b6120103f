#include "response_samples.hpp"

#include "petsc_handles.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

namespace rc::modes {

std::string response_samples_key(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, double ekman,
                                 long unknowns) {
  std::string key = shape.kind;
  for (const auto& [name, value] : shape.dims) key += fmt::format(" {}={:.17g}", name, value);
  if (shape.kind == "section") {
    std::ifstream in(shape.file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    key += fmt::format(" file-hash={:x}", std::hash<std::string>{}(text.str()));
  }
  key += fmt::format(" order={} size={:.17g} radial={:.17g} wall={:.17g} growth={:.17g} layer={:.17g} ekman={:.17g} "
                     "unknowns={}", mesh.order, mesh.size, mesh.radial_size, mesh.wall_size, mesh.wall_growth,
                     mesh.wall_layer, ekman, unknowns);
  return key;
}

ResponseSamples::ResponseSamples(std::filesystem::path path, std::string key)
    : path_(std::move(path)), key_(std::move(key)) {
  std::vector<double> flat;  // rank 0 reads, every rank gets the samples
  if (is_root_rank()) {
    std::ifstream in(path_);
    std::string line;
    if (in && std::getline(in, line) && line == "# key: " + key_) {
      fresh_ = false;
      double a, b, c, d;
      while (std::getline(in, line)) {
        std::istringstream row(line);
        if (row >> a >> b >> c >> d) flat.insert(flat.end(), {a, b, c, d});
      }
    }
  }
  long n = static_cast<long>(flat.size());
  int fresh = fresh_ ? 1 : 0;
  MPI_Bcast(&n, 1, MPI_LONG, 0, PETSC_COMM_WORLD);
  MPI_Bcast(&fresh, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  flat.resize(static_cast<std::size_t>(n));
  if (n > 0) MPI_Bcast(flat.data(), static_cast<int>(n), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  fresh_ = fresh != 0;
  for (std::size_t k = 0; k + 3 < flat.size(); k += 4) samples_[{flat[k], flat[k + 1]}] = {flat[k + 2], flat[k + 3]};
  read_ = samples_.size();
}

bool ResponseSamples::find(std::complex<double> sigma, std::complex<double>& R) const {
  const auto it = samples_.find({sigma.real(), sigma.imag()});
  if (it == samples_.end()) return false;
  R = it->second;
  return true;
}

void ResponseSamples::add(std::complex<double> sigma, std::complex<double> R) {
  if (path_.empty()) return;
  samples_[{sigma.real(), sigma.imag()}] = R;
  ++added_;
  if (!is_root_rank()) return;
  std::ofstream out(path_, fresh_ ? std::ios::trunc : std::ios::app);
  if (fresh_) out << "# key: " << key_ << "\n";
  fresh_ = false;
  out << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}\n", sigma.real(), sigma.imag(), R.real(), R.imag());
}

void ResponseSamples::remove() {
  if (path_.empty() || !is_root_rank()) return;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace rc::modes
