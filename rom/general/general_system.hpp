// The general chain's first-order form and its roots (docs/rom.md, "Bodies and tanks without axial symmetry").
// Body k's angular velocity in its own frame is ω0 e_z + δω_k, δω_k = P_k Q̇ + R_k Q with
//   δω_t = J q̇_k − ω0 q_k  (J = e_z ×),   δω_z = ψ̇_k,
// and its fluid's relative angular momentum h_k = Σ_l 2 Re(z_l c_l) − G_k δω_k (G_k the geostrophic weight: fluid at
// λ = 0 that stays at rest while the body turns) reacts on it as the moment −(ḣ_k + ω0 e_z × h_k), which in the
// coordinates Q is T_k ḣ_k + S_k h_k with T_k = P_kᵀ and S_k = ω0 on q_k. With each mode's ż = iλ z − c_left·δω̇
// (the ideal fluid's λ real and c_left = c̄; a damped mode's λ complex, general_tank.hpp):
//   (M − Σ PᵀN P) Q̈ = −(C − Σ(PᵀN R + S G P)) Q̇ − (K − Σ S G R) Q − Σ(PᵀW Λ + S W) Z,
//   Ż = Λ Z − Ĉ (P Q̈ + R Q̇),
// N_k = Σ_l 2 Re(c_l c_left,lᵀ) + G_k (the fluid that does not follow the body: with every ideal mode kept, the frozen
// fluid's inertia less Zhukovsky's), Z = (Re z_l, Im z_l), W and Ĉ the real forms of z ↦ 2 Re(z c) and x ↦ c_left·x.
// The state is y = (s q, Q̇, Z) (the axial angles ψ never enter: only their rates) and a root σ (y ∝ e^{iσt}) is σ = −i·eig(B),
// in the frame turning with the bodies.
#pragma once

#include "general_chain.hpp"
#include "verdict.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::rom {

struct GeneralSystem {
  Eigen::MatrixXd B;   // y' = B y
  Eigen::MatrixXd input;  // dim × dim_q: y' = B y + input F for a generalised force F on Q (a moment's rows)
  double s = 1;        // q is carried as s q
  double recoil_residual = -1;  // a free chain with partial fills: free_recoil.hpp's check of its reduction; else −1
  int dim() const { return static_cast<int>(B.rows()); }
};

// The maps above between the coordinates Q, the bodies' 3-vectors (3 per body, in F's axes) and the fluid's Z.
struct FluidMaps {
  Eigen::MatrixXd P, R;    // 3n × dim_q: δω = P Q̇ + R Q
  Eigen::MatrixXd S;       // dim_q × 3n: ω0 on each body's transverse components
  Eigen::MatrixXd N, G;    // 3n × 3n, block diagonal: the fluid that does not follow the body; the geostrophic part
  Eigen::MatrixXd W;       // 3n × 2m: Z ↦ h = Σ 2 Re(z c)
  Eigen::MatrixXd Chat;    // 2m × 3n: x ↦ (Re, Im) of c_left·x (ideal: c̄·x)
  Eigen::MatrixXd Lambda;  // 2m × 2m: z ↦ iλ z (λ complex for a damped mode)
};
FluidMaps fluid_maps(const GeneralChain& g);

// The inertia the bodies' accelerations see with the modes' share taken out, M − Σ_k P_kᵀ N_k P_k.
Eigen::MatrixXd effective_inertia(const GeneralChain& g);

// Throws SceneError (key "body") when effective_inertia is not positive definite: the shells must carry inertia of
// their own beyond what the fluid's modes take.
void check_effective_inertia(const Scene& scene, const GeneralChain& g);

// Throws std::runtime_error when its matrix is not finite (the scene's values overflow together). `s` > 0 fixes q's
// scale (a periodic chain's B(t) keeps one state), else it is chosen from the stiffness.
GeneralSystem build_general_system(const GeneralChain& g, double s = 0);

struct GeneralSpectrum {
  std::vector<std::complex<double>> roots;  // σ (rad/s) in the turning frame, ascending real part
  Verdict verdict;                          // as (26)'s (spectrum.hpp: verdict_of_roots)
  int floquet_steps = 0;                    // a periodic chain (floquet.hpp): Magnus steps per period, else 0
  double floquet_error = 0;                 // and how far its roots moved from half as many (rad/s)
  int floquet_unresolved = 0;               // roots decaying beyond the monodromy's precision (floquet.hpp)
  double recoil_residual = -1;              // a free chain with partial fills: its reduction's check (free_recoil.hpp)
};

// The roots of the chain, by Floquet's theory when its coefficients are periodic (floquet.hpp). Throws
// std::runtime_error when the eigen-solver does not converge.
GeneralSpectrum general_spectrum(const GeneralChain& g);

}  // namespace rc::rom
