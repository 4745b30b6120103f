#include "cluster_fields.hpp"

#include "lagrange_nodes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {
namespace {


}  // namespace

void fill_fields_mesh(const geometry::MeridianMesh& mesh, ModeFields& f) {
  const geometry::TriangleNodes ref = geometry::triangle_nodes(mesh.order);
  for (const auto& x : mesh.nodes) f.points.insert(f.points.end(), {x[0], 0.0, x[1]});
  f.order = mesh.order;
  f.elements = mesh.triangles;
  const int npe = mesh.nodes_per_element;
  for (std::size_t e = 0; e < mesh.num_triangles(); ++e)
    for (const auto& s : ref.sub_triangles)
      for (int a : s) f.cells.push_back(mesh.triangles[e * npe + a]);
}

namespace {

// p, p_r, p_z at the mesh nodes from a dof vector. The FE gradient jumps across elements; a node's value
// is the mean over the elements that share it.
class NodalGradient {
 public:
  NodalGradient(const FESpace& space, const geometry::TriangleNodes& ref) : space_(space) {
    const auto& mesh = space.mesh();
    const int npe = mesh.nodes_per_element;
    grad_.resize(mesh.num_triangles() * npe * npe * 2);
    sharing_.assign(mesh.nodes.size(), 0);
    for (std::size_t e = 0; e < mesh.num_triangles(); ++e) {
      const int* nodes = &mesh.triangles[e * npe];
      for (int b = 0; b < npe; ++b) {
        ++sharing_[nodes[b]];
        // Isoparametric Jacobian at node b, then grad_x N_a = J^{-T} grad_u N_a (as FESpace::quadrature).
        double ru = 0, rv = 0, zu = 0, zv = 0;
        for (int a = 0; a < npe; ++a) {
          const double du = ref.dN[(b * npe + a) * 2], dv = ref.dN[(b * npe + a) * 2 + 1];
          const auto& x = mesh.nodes[nodes[a]];
          ru += du * x[0]; rv += dv * x[0];
          zu += du * x[1]; zv += dv * x[1];
        }
        const double det = ru * zv - rv * zu;
        for (int a = 0; a < npe; ++a) {
          const double du = ref.dN[(b * npe + a) * 2], dv = ref.dN[(b * npe + a) * 2 + 1];
          double* g = &grad_[((e * npe + b) * npe + a) * 2];
          g[0] = (zv * du - zu * dv) / det;
          g[1] = (-rv * du + ru * dv) / det;
        }
      }
    }
  }

  // p, p_r, p_z at every node (size: number of mesh nodes).
  void evaluate(const std::vector<double>& dofs, std::vector<double>& p, std::vector<double>& pr,
                std::vector<double>& pz) const {
    const auto& mesh = space_.mesh();
    const int npe = mesh.nodes_per_element;
    const std::size_t n = mesh.nodes.size();
    p.assign(n, 0.0);
    pr.assign(n, 0.0);
    pz.assign(n, 0.0);
    for (std::size_t e = 0; e < mesh.num_triangles(); ++e) {
      const auto d = space_.element_dofs(e);
      const int* nodes = &mesh.triangles[e * npe];
      for (int b = 0; b < npe; ++b) {
        if (d[b] >= 0) p[nodes[b]] = dofs[d[b]];
        for (int a = 0; a < npe; ++a) {
          if (d[a] < 0) continue;  // p = 0 on the axis
          const double* g = &grad_[((e * npe + b) * npe + a) * 2];
          pr[nodes[b]] += g[0] * dofs[d[a]];
          pz[nodes[b]] += g[1] * dofs[d[a]];
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      pr[i] /= sharing_[i];
      pz[i] /= sharing_[i];
    }
  }

 private:
  const FESpace& space_;
  std::vector<double> grad_;  // [((e * npe + b) * npe + a) * 2 + d]: d/dr (d = 0), d/dz (d = 1) of N_a at node b
  std::vector<int> sharing_;  // elements sharing each node
};

PVec to_petsc(const std::vector<double>& v) {
  PVec x;
  petsc_check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(v.size()), x.out()), "VecCreateSeq");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(x, &a), "VecGetArray");
  std::copy(v.begin(), v.end(), a);
  petsc_check(VecRestoreArray(x, &a), "VecRestoreArray");
  return x;
}

double dot(Vec x, Vec y) {
  PetscScalar s = 0;
  petsc_check(VecDot(x, y, &s), "VecDot");
  return static_cast<double>(s);
}

// The eigenpairs that form the cluster of a /modes row (header comment).
std::vector<Eigenpair> cluster_members(const QuadraticEigenSolver& solver, double lambda, double width,
                                       std::size_t row) {
  const double delta = width * std::max(std::abs(lambda), 0.1);
  // Stay inside (−2, 2), where every eigenvalue lies (as clusters.cpp).
  const double lo = std::max(lambda - 2 * delta, -1.999999), hi = std::min(lambda + 2 * delta, 1.999999);
  auto pairs = solver.solve_interval(lo, hi).pairs;
  if (pairs.empty())
    throw std::runtime_error(fmt::format("fields: no eigenpair within {:.3g} of mode {} (lambda = {:.12g})",
                                         2 * delta, row, lambda));
  const auto peak = *std::max_element(pairs.begin(), pairs.end(),
                                      [](const Eigenpair& a, const Eigenpair& b) { return a.coupling.E < b.coupling.E; });
  std::erase_if(pairs, [&](const Eigenpair& p) { return std::abs(p.lambda - peak.lambda) > delta; });
  for (const auto& p : pairs)
    if (std::abs(p.lambda) < 1e-12) throw std::runtime_error("fields: a cluster member has lambda = 0");
  return pairs;
}

// Coefficients c_l of W = Σ c_l V_l (normalised: N²(W) = 1) and a(W), from the assembled forms:
//   a(V_l)        = −π [f1·p_l/(2 − λ_l) + f2·p_l/λ_l]                                  (docs/physics.md §2)
//   (V_l, V_k)    = 2π [((λ_l λ_k + 4) p_lᵀKh p_k + 2(λ_l + λ_k) p_lᵀGc p_k)/(D_l D_k) + p_lᵀKz p_k/(λ_l λ_k)]
// (the second is docs/physics.md §2's ‖V‖² polarised; for l = k it is coupling.hpp's ‖Ṽ‖²/(λD)²).
struct Combination {
  std::vector<double> c;
  double a = 0;
};

Combination combine(const PoincareForms& forms, const std::vector<Eigenpair>& members) {
  const std::size_t k = members.size();
  std::vector<PVec> x, khx, kzx, gcx;
  for (const auto& m : members) {
    x.push_back(to_petsc(m.p));
    const std::pair<Mat, std::vector<PVec>*> products[] = {{forms.Kh, &khx}, {forms.Kz, &kzx}, {forms.Gc, &gcx}};
    for (const auto& [A, out] : products) {
      PVec y;
      petsc_check(VecDuplicate(x.back(), y.out()), "VecDuplicate");
      petsc_check(MatMult(A, x.back(), y), "MatMult");
      out->push_back(std::move(y));
    }
  }
  std::vector<double> a(k), gram(k * k);
  for (std::size_t l = 0; l < k; ++l) {
    const double ll = members[l].lambda, Dl = 4 - ll * ll;
    a[l] = -std::numbers::pi * (dot(forms.f1, x[l]) / (2 - ll) + dot(forms.f2, x[l]) / ll);
    for (std::size_t j = 0; j < k; ++j) {
      const double lj = members[j].lambda, Dj = 4 - lj * lj;
      gram[l * k + j] = 2 * std::numbers::pi * (((ll * lj + 4) * dot(x[l], khx[j]) + 2 * (ll + lj) * dot(x[l], gcx[j])) / (Dl * Dj) +
                                   dot(x[l], kzx[j]) / (ll * lj));
    }
  }
  Combination w;
  w.c.resize(k);
  for (std::size_t l = 0; l < k; ++l) w.c[l] = a[l] / gram[l * k + l];
  double norm2 = 0;
  for (std::size_t l = 0; l < k; ++l)
    for (std::size_t j = 0; j < k; ++j) norm2 += w.c[l] * gram[l * k + j] * w.c[j];
  if (!(norm2 > 0)) throw std::runtime_error("fields: a cluster carries no coupling flow (a = 0)");
  const double scale = 1 / std::sqrt(norm2);
  for (std::size_t l = 0; l < k; ++l) {
    w.c[l] *= scale;
    w.a += w.c[l] * a[l];
  }
  return w;
}

// p, V and the kinetic-energy density of W at the nodes (header comment for V from p).
ModeFields::Mode nodal_field(const NodalGradient& gradient, const geometry::MeridianMesh& mesh,
                             const std::vector<Eigenpair>& members, const Combination& w) {
  const std::size_t n = mesh.nodes.size();
  std::vector<bool> on_axis(n, false);
  for (int i : mesh.axis_nodes) on_axis[i] = true;
  ModeFields::Mode m;
  m.p.assign(n, 0.0);
  m.V.assign(3 * n, 0.0);
  std::vector<double> p, pr, pz;
  for (std::size_t l = 0; l < members.size(); ++l) {
    gradient.evaluate(members[l].p, p, pr, pz);
    const double lam = members[l].lambda, D = 4 - lam * lam, c = w.c[l];
    for (std::size_t i = 0; i < n; ++i) {
      const double p_over_r = on_axis[i] ? pr[i] : p[i] / mesh.nodes[i][0];
      m.p[i] += c * p[i];
      m.V[3 * i] += c * -(lam * pr[i] + 2 * p_over_r) / D;
      m.V[3 * i + 1] += c * (2 * pr[i] + lam * p_over_r) / D;
      m.V[3 * i + 2] += c * pz[i] / lam;
    }
  }
  m.energy_density.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = &m.V[3 * i];
    m.energy_density[i] = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * mesh.nodes[i][0];
  }
  m.members = static_cast<int>(members.size());
  for (const auto& e : members) m.E_members += e.coupling.E;
  m.a = w.a;
  return m;
}

}  // namespace

ModeFields weighted_mode_fields(const FESpace& space, const std::vector<WeightedPressure>& rows) {
  ModeFields f;
  fill_fields_mesh(space.mesh(), f);
  const NodalGradient gradient(space, geometry::triangle_nodes(space.mesh().order));
  for (std::size_t row = 0; row < rows.size(); ++row) {
    Eigenpair member;
    member.lambda = rows[row].lambda;
    member.p = *rows[row].p;
    member.coupling.E = rows[row].E;
    ModeFields::Mode m = nodal_field(gradient, space.mesh(), {member}, Combination{{rows[row].weight}, rows[row].a});
    m.row = row;
    m.lambda = rows[row].lambda;
    f.modes.push_back(std::move(m));
  }
  return f;
}

ModeFields cluster_fields(const FESpace& space, const PoincareForms& forms, const ModeTable& table,
                          const FieldSettings& settings,
                          const std::function<void(std::size_t, std::size_t)>& progress) {
  const auto& mesh = space.mesh();
  const geometry::TriangleNodes ref = geometry::triangle_nodes(mesh.order);
  ModeFields f;
  fill_fields_mesh(mesh, f);
  const NodalGradient gradient(space, ref);
  QepSettings qep = settings.qep;
  qep.keep_eigenvectors = true;
  const QuadraticEigenSolver solver(forms, qep);
  for (std::size_t row = 0; row < table.size(); ++row) {
    const auto members = cluster_members(solver, table.lambda[row], settings.cluster_width, row);
    ModeFields::Mode m = nodal_field(gradient, mesh, members, combine(forms, members));
    m.row = row;
    m.lambda = table.lambda[row];
    f.modes.push_back(std::move(m));
    if (progress) progress(row + 1, table.size());
  }
  return f;
}

}  // namespace rc::modes
