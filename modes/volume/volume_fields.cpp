#include "volume_fields.hpp"

#include "qep_solver.hpp"
#include "tetrahedron_nodes.hpp"
#include "volume_coupling.hpp"

#include "eigen_dense.hpp"
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rc::modes {
namespace {

using C = std::complex<double>;

// P and ∇P at the mesh nodes from a real-form dof vector. The FE gradient jumps across elements; a node's value is
// the mean over the elements that share it (as the meridian fields, modes/ideal/cluster_fields.cpp).
class NodalGradient {
 public:
  NodalGradient(const VolumeSpace& space, const geometry::TetrahedronNodes& ref) : space_(space), ref_(ref) {
    const auto& mesh = space.mesh();
    const int npe = mesh.nodes_per_element;
    inverse_jacobian_.resize(mesh.num_tetrahedra() * npe);
    sharing_.assign(mesh.nodes.size(), 0);
    for (std::size_t e = 0; e < mesh.num_tetrahedra(); ++e) {
      const int* nodes = &mesh.tetrahedra[e * npe];
      for (int b = 0; b < npe; ++b) {
        ++sharing_[nodes[b]];
        Eigen::Matrix3d J = Eigen::Matrix3d::Zero();  // J(d, k) = ∂x_d/∂u_k at node b (isoparametric)
        for (int a = 0; a < npe; ++a)
          for (int d = 0; d < 3; ++d)
            for (int k = 0; k < 3; ++k) J(d, k) += mesh.nodes[nodes[a]][d] * ref.dN[(b * npe + a) * 3 + k];
        inverse_jacobian_[e * npe + b] = J.inverse().transpose();  // ∇_x = J⁻ᵀ ∇_u
      }
    }
  }

  // P and ∇P at every mesh node for the complex pressure of real form p (P_r then P_i).
  void evaluate(const std::vector<double>& p, std::vector<C>& P, std::vector<Eigen::Vector3cd>& g) const {
    const auto& mesh = space_.mesh();
    const int npe = mesh.nodes_per_element, n = space_.ndof();
    P.assign(mesh.nodes.size(), 0.0);
    g.assign(mesh.nodes.size(), Eigen::Vector3cd::Zero());
    for (std::size_t e = 0; e < mesh.num_tetrahedra(); ++e) {
      const auto dofs = space_.element_dofs(e);
      const int* nodes = &mesh.tetrahedra[e * npe];
      for (int b = 0; b < npe; ++b) {
        if (dofs[b] >= 0) P[nodes[b]] = C(p[dofs[b]], p[n + dofs[b]]);
        Eigen::Vector3cd gu = Eigen::Vector3cd::Zero();
        for (int a = 0; a < npe; ++a) {
          if (dofs[a] < 0) continue;  // the pinned node: P = 0
          const double* dN = &ref_.dN[(b * npe + a) * 3];
          gu += C(p[dofs[a]], p[n + dofs[a]]) * Eigen::Vector3cd(dN[0], dN[1], dN[2]);
        }
        g[nodes[b]] += inverse_jacobian_[e * npe + b].cast<C>() * gu;
      }
    }
    for (std::size_t k = 0; k < g.size(); ++k) g[k] /= std::max(sharing_[k], 1);
  }

 private:
  const VolumeSpace& space_;
  const geometry::TetrahedronNodes& ref_;
  std::vector<Eigen::Matrix3d> inverse_jacobian_;
  std::vector<int> sharing_;
};

void fill_mesh(const VolumeSpace& space, const geometry::TetrahedronNodes& ref, ModeFields& f) {
  const auto& mesh = space.mesh();
  f.dimension = 3;
  f.order = mesh.order;
  for (const auto& x : mesh.nodes) f.points.insert(f.points.end(), x.begin(), x.end());
  f.elements = mesh.tetrahedra;
  const int npe = mesh.nodes_per_element;
  for (std::size_t e = 0; e < mesh.num_tetrahedra(); ++e)
    for (const auto& s : ref.sub_tetrahedra)
      for (int a : s) f.cells.push_back(mesh.tetrahedra[e * npe + a]);
}

Eigen::Matrix3cd row_tensor(const ModeTable& t, std::size_t row) {
  Eigen::Matrix3cd H;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      H(j, k) = C(t.volume_cavity.coupling_re[9 * row + 3 * j + k], t.volume_cavity.coupling_im[9 * row + 3 * j + k]);
  return H;
}

// The axis u of the row's largest coupling (unit, complex) and that eigenvalue.
std::pair<Eigen::Vector3cd, double> principal_axis(const ModeTable& t, std::size_t row) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd> es(row_tensor(t, row));
  return {es.eigenvectors().col(2), es.eigenvalues()(2)};
}

// A row's modes: the pencil's eigenpairs within its window. Each complex mode appears twice in the real form
// ((P_r, P_i) and (−P_i, P_r), i.e. P and iP), whose terms of the projection coincide: each gets half the weight.
ModeFields::Mode row_field(const VolumeSpace& space, const std::array<double, 3>& centroid, const NodalGradient& grad,
                           const QepSolution& pairs, const Eigen::Vector3cd& u) {
  std::vector<PressureMember> members;
  ModeFields::Mode m;
  for (const auto& pair : pairs.pairs) {
    const auto pc = pressure_mode_coupling(space, centroid, pair.lambda, pair.p);
    members.push_back({pair.lambda, &pair.p, 0.5 * pc.c.dot(u) / pc.norm2});  // dot: c_lᴴ u
    const Eigen::Matrix3cd H = pc.tensor();
    m.E_members += 0.5 * (H(0, 0) + H(1, 1)).real();
  }
  const auto whole = combined_mode_coupling(space, centroid, members);
  const C coupling = u.dot(whole.c);  // uᴴ c
  const C phase = std::abs(coupling) > 0 ? std::conj(coupling) / std::abs(coupling) : C(1.0);
  const double scale = 1 / std::sqrt(whole.norm2);
  m.a = std::abs(coupling) * scale;
  m.members = static_cast<int>((pairs.pairs.size() + 1) / 2);
  const std::size_t n = space.mesh().nodes.size();
  std::vector<C> P(n, 0.0), Pl;
  std::vector<Eigen::Vector3cd> V(n, Eigen::Vector3cd::Zero()), g;
  for (const auto& member : members) {
    grad.evaluate(*member.p, Pl, g);
    const C w = member.weight * phase * scale;
    for (std::size_t k = 0; k < n; ++k) {
      P[k] += w * Pl[k];
      V[k] += w * velocity_from_pressure_gradient(member.lambda, g[k]);
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    m.p.push_back(P[k].real());
    m.p_imag.push_back(P[k].imag());
    for (int d = 0; d < 3; ++d) {
      m.V.push_back(V[k](d).real());
      m.V_imag.push_back(V[k](d).imag());
    }
    m.energy_density.push_back(V[k].squaredNorm());
  }
  return m;
}

}  // namespace

double largest_coupling(const ModeTable& table, std::size_t row) { return principal_axis(table, row).second; }

ModeFields volume_mode_fields(const VolumeSpace& space, const VolumeForms& forms, const std::array<double, 3>& centroid,
                              const ModeTable& table, const std::function<void(const std::string&)>& progress) {
  const auto ref = geometry::tetrahedron_nodes(space.order());
  ModeFields f;
  fill_mesh(space, ref, f);
  const NodalGradient grad(space, ref);
  const auto pencil = real_form_pencil(forms);
  QepSettings settings;
  settings.keep_eigenvectors = true;
  const QuadraticEigenSolver solver(pencil, settings);
  for (std::size_t row = 0; row < table.size(); ++row) {
    const double lambda = table.lambda[row];
    // The row's cluster merged Ritz values within 1e-5 · max(λ, 0.1) (VolumeSurveySettings::merge_width); the
    // window stops half-way to the nearest other row, whose modes are its own.
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t other = 0; other < table.size(); ++other)
      if (other != row) gap = std::min(gap, std::abs(table.lambda[other] - lambda));
    const double half = std::min(std::max(2e-5 * std::max(lambda, 0.1), 2 * table.spread[row]), 0.5 * gap);
    if (progress) progress(fmt::format("fields: row {} of {}, the pencil's eigenpairs within {:.1e} of {:.9f}", row + 1,
                                       table.size(), half, lambda));
    const auto pairs = solver.solve_interval(lambda - half, lambda + half);
    if (pairs.pairs.empty())
      throw std::runtime_error(fmt::format("--fields: the pressure pencil has no eigenpair within {:.1e} of row {}'s "
                                           "lambda {:.12g}", half, row + 1, lambda));
    ModeFields::Mode m = row_field(space, centroid, grad, pairs, principal_axis(table, row).first);
    m.row = row;
    m.lambda = lambda;
    f.modes.push_back(std::move(m));
  }
  f.validate();
  return f;
}

}  // namespace rc::modes
