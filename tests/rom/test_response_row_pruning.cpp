// A response table's rows no root needs (rom/model/response_row_pruning.hpp): a table of three resonances in its window,
// one heavy pole beyond it and two hundred far poles of tiny residue. The tiny ones are left out and the heavy one
// kept; the chain's roots with and without them (`prune = false`) agree to far less than the 1e-4 of a decay the
// allowance gives, and a table whose far rows are too heavy for it keeps them all.
#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "response_fit_rows.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

ChainModel chain(const std::string& file, bool prune) {
  std::ostringstream s;
  s.precision(17);
  s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = 0.001\ncom = 0.0\nspin = 100"
    << "\n[body.cavity]\ntable = \"" << file << "\"\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nviscosity = "
    << 1e-3 * 100 * 0.05 * 0.05 << "\nprune = " << (prune ? "true" : "false") << "\n";
  return build_model(parse_scene_text(s.str(), ".", "pruning"));
}

std::vector<cd> body_roots(const ChainModel& m) {
  std::vector<cd> out;
  for (const Root& r : compute_spectrum(m).roots)
    if (r.owner.rfind("body", 0) == 0 && std::abs(r.sigma) > 1e-9) out.push_back(r.sigma);
  return out;
}

}  // namespace

TEST(ResponseRowPruning, FarRowsOfTinyResidueAreLeftOutAndTheRootsStay) {
  std::vector<cd> poles = {{0.5, 0.02}, {-0.8, 0.05}, {1.4, 0.03}, {20.0, 2.0}};
  std::vector<cd> residues = {{0.3, 0.01}, {0.1, -0.005}, {0.05, 0.002}, {0.2, 0.0}};
  for (int l = 0; l < 200; ++l) {
    poles.emplace_back((l % 2 ? 1 : -1) * (10.0 + l), 1.0 + 0.1 * l);
    residues.emplace_back(1e-13, 1e-14);
  }
  const std::string file = test::write_response_fit(poles, residues, 1e-4, "pruning_fit.h5");
  const ChainModel pruned = chain(file, true), all = chain(file, false);
  std::vector<int> kept;
  for (const FluidMode& md : pruned.modes) kept.push_back(md.table_index);
  const bool heavy_kept = std::any_of(pruned.modes.begin(), pruned.modes.end(),
                                      [](const FluidMode& md) { return md.lambda_table == 20.0; });
  const std::vector<cd> a = body_roots(pruned), b = body_roots(all);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  double moved = 0, rate = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    moved = std::max(moved, std::abs(a[k] - b[k]) / std::abs(b[k]));
    rate = std::max(rate, std::abs(a[k].imag() - b[k].imag()) / std::abs(b[k].imag()));
  }
  std::printf("rows kept %zu of %zu (%d left out); the heavy pole beyond the window %s; %zu body roots moved by %.2e "
              "(their decays by %.2e of themselves)\n", pruned.modes.size(), all.modes.size(),
              pruned.bodies[0].pruned_rows, heavy_kept ? "kept" : "LEFT OUT", a.size(), moved, rate);
  EXPECT_EQ(all.modes.size(), 204u);
  EXPECT_EQ(pruned.bodies[0].pruned_rows, 200);
  EXPECT_EQ(pruned.modes.size(), 4u);
  EXPECT_TRUE(heavy_kept);
  EXPECT_LT(rate, 1e-4);
  EXPECT_LT(moved, 1e-6);

  // The same far rows 1e8 times heavier (1e-5 each): together they matter on the window, and the allowance keeps
  // most of them.
  for (std::size_t l = 4; l < residues.size(); ++l) residues[l] *= 1e8;
  const std::string heavy_file = test::write_response_fit(poles, residues, 1e-4, "pruning_heavy_fit.h5");
  const ChainModel heavy = chain(heavy_file, true);
  const std::vector<cd> c = body_roots(heavy), d = body_roots(chain(heavy_file, false));
  ASSERT_EQ(c.size(), d.size());
  double heavy_rate = 0;
  for (std::size_t k = 0; k < c.size(); ++k)
    heavy_rate = std::max(heavy_rate, std::abs(c[k].imag() - d[k].imag()) / std::abs(d[k].imag()));
  std::printf("heavier far rows: %d left out of %zu; the decays moved by %.2e of themselves\n",
              heavy.bodies[0].pruned_rows, heavy.modes.size() + static_cast<std::size_t>(heavy.bodies[0].pruned_rows),
              heavy_rate);
  EXPECT_LT(heavy.bodies[0].pruned_rows, 200);
  EXPECT_LT(heavy_rate, 1e-4);
}

}  // namespace rc::rom
