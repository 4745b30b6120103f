// The spins' own motion in the linear chain (docs/rom.md, "Axial rotations"): the axial rotations that (26) holds
// constant, as states of their own. At first order they decouple from the tilts (the bodies are axisymmetric, and a
// spin's change enters the tilts' gyroscopic terms only times a tilt rate), so they obey, exactly as the nonlinear
// chain does at zero tilt,
//   C_k ω̇_k = −β_k (ω_k − ω_{k−1}) + β_{k+1} (ω_{k+1} − ω_k) + M_k(t),     ψ̇_k = ω_k − ω_k0,
// with C_k the shell's axial inertia: an ideal liquid does not follow its tank's turns about the symmetry axis (Batyr
// (2010) (34)–(42): the liquid enters the inertia through the projection on potential fields, P_G(e3 × r) = 0 for an
// axisymmetric cavity; docs/physics.md §3, "Axial rotations"; the nonlinear chain holds it as a gyrostat's momentum),
// β_k the axial friction of joint k (β_1 against the support, ω_0 = 0 there), M_k the axial moments of [body.moment]
// (axial, and the z parts of space and harmonic), and ψ_k the angle gained on the reference rotation ω_k0 t.
// Batyr (2010), Lemma 1 and Properties 1, 6, 7, 10: the roots (e^{iσt}) are σ = 0, n times with its eigenvectors the
// new rest angles, and σ = iμ_j with μ_j ≥ 0 the eigenvalues of C^{-1/2} D C^{-1/2} (D the friction's tridiagonal
// matrix); each μ_j = 0 (no friction, or none to the support: the common rotation) adds a zero with a Jordan chain
// of length two — a uniform change of spin (Batyr (89)).
#pragma once

#include "scene.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::rom {

struct AxialChain {
  Eigen::VectorXd C;         // axial inertia per body, kg m²: the shell's (its liquid does not follow)
  Eigen::MatrixXd D;         // axial friction, N m s: tridiagonal, positive semi-definite
  Eigen::VectorXd spin0;     // ω_k0, rad/s
  Eigen::VectorXd start;     // ω_k(0) − ω_k0, rad/s ([initial] axial_rate; Batyr (89) without friction)
  Eigen::VectorXd moment;    // constant axial moments, N m
  Eigen::VectorXd harmonic;  // amplitudes of the harmonic axial moments (· sin(2π f_k t)), N m
  Eigen::VectorXd frequency; // f_k, Hz
  bool moves() const;        // some friction, moment or initial change: the spins move
};

struct AxialSpectrum {
  std::vector<std::complex<double>> roots;  // 2n: the zeros first, then iμ_j ascending
  Eigen::VectorXd decay;                    // μ_j, 1/s, ascending (zeros included)
  int zeros = 0;                            // algebraic multiplicity of σ = 0
  int zero_eigenvectors = 0;                // geometric: n (the rest angles); zeros − n Jordan chains of length 2
};

struct AxialHistory {
  Eigen::MatrixXd spin;   // steps × n: ω_k(t), rad/s
  Eigen::MatrixXd angle;  // steps × n: ψ_k(t), rad
};

// From the scene: C_k from `inertia` (the shells' C), the frictions and axial moments.
AxialChain axial_chain(const Scene& scene, const std::vector<double>& inertia);

AxialSpectrum axial_spectrum(const AxialChain& a);

// ω(t) and ψ(t) in closed form at the times t (ω(0) = ω_k0 + start, ψ(0) = 0): the modal solution of the symmetric system
// y = C^{1/2} ω, ẏ = −C^{-1/2} D C^{-1/2} y + C^{-1/2} M(t), constant and harmonic parts summed.
AxialHistory axial_history(const AxialChain& a, const std::vector<double>& t);

}  // namespace rc::rom
