// Round trip and rejection tests for the HDF5 mode table (docs/physics.md §4).
#include "mode_table.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {
rc::ModeTable sample() {
  rc::ModeTable t;
  t.shape = "cylinder";
  t.dimensions = {{"radius", 1.0}, {"height", 2.0}};
  t.fe_order = 3; t.mesh_h = 0.1; t.ndof = 1234; t.m = 1;
  t.volume = 6.28; t.centroid_z = 0; t.A_f = 2.5; t.C_f = 3.1; t.J_zh = 0.3;
  t.sum_rule = 2.2; t.coverage = 0.97; t.solver = "test"; t.tolerance = 1e-12; t.wall_seconds = 0.1;
  t.kappa = {2.5, 2.00897}; t.lambda = {0.8, 2 / 2.00897}; t.E = {0.01, 2.0544};
  t.a = {std::sqrt(0.005), 1.0}; t.N2 = {1.0, 2 / 2.0544}; t.residual = {1e-12, 1e-13};  // E = 2a²/N²
  t.spread = {0, 1e-9}; t.members = {1, 3};
  t.dlambda = {1e-3, 1e-12}; t.dE = {0.5, 1e-10}; t.converged = {0, 1};
  t.convergence_reference = "order 5, same mesh"; t.convergence_tolerance = 1e-6;
  t.bands.lo = {-2, 0}; t.bands.hi = {0, 2}; t.bands.E = {0.1, 2.1}; t.bands.lambda_mean = {-0.6, 0.99};
  return t;
}
}  // namespace

TEST(ModeTable, RoundTripSortsByEnergyAndKeepsAttributes) {
  auto t = sample();
  t.sort_by_energy();
  EXPECT_DOUBLE_EQ(t.E[0], 2.0544);
  EXPECT_EQ(t.members[0], 3);
  fs::path p = fs::temp_directory_path() / "rc_mode_table_roundtrip.h5";
  rc::write_mode_table(t, p);
  auto r = rc::read_mode_table(p);
  EXPECT_EQ(r.shape, "cylinder");
  EXPECT_DOUBLE_EQ(r.dimensions.at("height"), 2.0);
  EXPECT_EQ(r.ndof, 1234);
  EXPECT_DOUBLE_EQ(r.J_zh, 0.3);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r.kappa[0], 2.00897);
  EXPECT_EQ(r.members[1], 1);
  EXPECT_EQ(r.converged[0], 1);  // sorted with its cluster
  EXPECT_DOUBLE_EQ(r.dE[1], 0.5);
  EXPECT_EQ(r.convergence_reference, "order 5, same mesh");
  EXPECT_DOUBLE_EQ(r.convergence_tolerance, 1e-6);
  ASSERT_EQ(r.bands.size(), 2u);
  EXPECT_DOUBLE_EQ(r.bands.lambda_mean[1], 0.99);
  fs::remove(p);
}

TEST(ModeTable, RejectsNonTablesWithACause) {
  fs::path p = fs::temp_directory_path() / "rc_not_a_table.h5";
  { std::ofstream(p) << "hello"; }
  try {
    rc::read_mode_table(p);
    FAIL() << "a text file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an HDF5 file"), std::string::npos) << e.what();
  }
  fs::remove(p);
  EXPECT_THROW(rc::read_mode_table("/nonexistent/x.h5"), std::runtime_error);
}

TEST(ModeTable, InvalidTableLeavesNoFile) {
  auto t = sample();
  t.E.pop_back();  // inconsistent lengths
  fs::path p = fs::temp_directory_path() / "rc_bad_table.h5";
  fs::remove(p);
  EXPECT_THROW(rc::write_mode_table(t, p), std::runtime_error);
  EXPECT_FALSE(fs::exists(p));
}

// Format version 2: a viscous table keeps its decay and complex coupling; an ideal table has none of them.
namespace {
// A one-row viscous table of the unit sphere (its damped spin-over mode at Ek = 1e-4).
rc::ModeTable viscous_sample() {
  rc::ModeTable t;
  t.shape = "sphere";
  t.dimensions = {{"radius", 1.0}};
  t.kappa = {2.0}; t.lambda = {1.0}; t.E = {1.6}; t.N2 = {1.0}; t.residual = {1e-12};
  t.volume = 4.18879020479; t.A_f = 1.67551608191; t.C_f = t.A_f; t.sum_rule = t.A_f;
  t.ekman = 1e-4;
  t.decay = {0.027}; t.E_imag = {-0.08};
  const std::complex<double> a_c = std::sqrt(std::complex<double>(1.6, -0.08) / 2.0);  // E_c = 2 a_c² (N² = 1)
  t.a = {a_c.real()}; t.a_imag = {a_c.imag()};
  return t;
}
}  // namespace

TEST(ModeTable, ViscousFieldsRoundTrip) {
  rc::ModeTable t = viscous_sample();
  t.mesh_h_wall = 0.01;
  const std::complex<double> a_c(t.a[0], t.a_imag[0]);
  const auto p = std::filesystem::temp_directory_path() / "rc_viscous_roundtrip.h5";
  rc::write_mode_table(t, p);
  const auto r = rc::read_mode_table(p);
  EXPECT_EQ(r.ekman, 1e-4);
  EXPECT_EQ(r.mesh_h_wall, 0.01);
  ASSERT_EQ(r.decay.size(), 1u);
  EXPECT_EQ(r.decay[0], 0.027);
  EXPECT_EQ(r.E_imag[0], -0.08);
  EXPECT_EQ(r.a_imag[0], a_c.imag());
  std::filesystem::remove(p);

  auto growing = t;
  growing.decay = {-0.1};
  EXPECT_THROW(growing.validate(), std::runtime_error);
  auto ideal_with_decay = t;
  ideal_with_decay.ekman = 0;
  EXPECT_THROW(ideal_with_decay.validate(), std::runtime_error);
  auto missing = t;
  missing.E_imag.clear();
  EXPECT_THROW(missing.validate(), std::runtime_error);
}

// A Krylov table's Im R error profile (/fit_decay) is read back as written, and one that does not describe the
// window (unsorted, outside it, negative, of another length, without fit_decay_error) is refused.
TEST(ModeTable, FitDecayProfileRoundTripsAndIsChecked) {
  rc::ModeTable t = viscous_sample();
  t.fit_lo = -1; t.fit_hi = 2; t.fit_error = 1e-5; t.fit_decay_error = 0.03;
  t.fit_decay_s = {-1, 0.5, 2};
  t.fit_decay_profile = {1e-3, 0.03, 2e-4};
  const auto p = std::filesystem::temp_directory_path() / "rc_fit_decay_roundtrip.h5";
  rc::write_mode_table(t, p);
  const auto r = rc::read_mode_table(p);
  std::filesystem::remove(p);
  EXPECT_EQ(r.fit_decay_s, t.fit_decay_s);
  EXPECT_EQ(r.fit_decay_profile, t.fit_decay_profile);
  const auto refused = [&](auto change) {
    rc::ModeTable b = t;
    change(b);
    EXPECT_THROW(b.validate(), std::runtime_error);
  };
  refused([](rc::ModeTable& b) { b.fit_decay_s = {-1, 2, 0.5}; });
  refused([](rc::ModeTable& b) { b.fit_decay_s = {-1, 0.5, 2.5}; });
  refused([](rc::ModeTable& b) { b.fit_decay_profile = {1e-3, -0.03, 2e-4}; });
  refused([](rc::ModeTable& b) { b.fit_decay_profile.pop_back(); });
  refused([](rc::ModeTable& b) { b.fit_decay_error = -1; });
}

// A table that breaks one of its identities (docs/physics.md §2) is refused, naming the identity.
TEST(ModeTable, IdentitiesAreCheckedOnReading) {
  const auto expect_identity = [](rc::ModeTable t, const char* what) {
    try {
      t.validate();
      ADD_FAILURE() << "accepted a table breaking " << what;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  sample().validate();
  auto t = sample();
  t.lambda[0] = 0;
  expect_identity(t, "lambda != 0");
  t = sample();
  t.kappa[0] = 3;
  expect_identity(t, "kappa = 2/lambda");
  t = sample();
  t.N2[0] = -1;
  expect_identity(t, "N2 > 0");
  t = sample();
  t.a[0] = -t.a[0];
  expect_identity(t, "a >= 0");
  t = sample();
  t.E[0] *= 1.01;
  expect_identity(t, "E = 2 a^2/N2");
  t = sample();
  t.kappa[1] = 0.5;
  t.lambda[1] = 4;
  expect_identity(t, "|lambda| <= 2");
  t = sample();
  t.sum_rule = 2.3;
  expect_identity(t, "sum_rule = A_f - J_zh");
  t = sample();
  t.dE.clear();
  expect_identity(t, "come together");
  t = sample();
  t.volume = 0;
  expect_identity(t, "volume > 0");
}

// A table is a file users exchange: reading one must be memory-safe whatever it holds. A root attribute read into
// one number that holds 4000 (or 2) elements used to be read past its one stack slot (AddressSanitizer); a NaN in
// /modes/E was accepted. Each is now refused with one line naming it. Written tables carry HDF5's checksummed
// metadata (superblock version 2).
namespace {
void replace_root_attribute(const fs::path& file, const char* name, std::size_t count) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5Adelete(f, name);
  const hsize_t n = count;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t a = H5Acreate2(f, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  const std::vector<double> values(count, 0.5);
  H5Awrite(a, H5T_NATIVE_DOUBLE, values.data());
  H5Aclose(a);
  H5Sclose(space);
  H5Fclose(f);
}

std::string read_error(const fs::path& file) {
  try {
    rc::read_mode_table(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "read without error";
}
}  // namespace

TEST(ModeTable, AttributesOfTheWrongSizeAreRefusedNotRead) {
  const fs::path p = fs::temp_directory_path() / "rc_table_sizes.h5";
  for (const auto& [name, count] : std::vector<std::pair<const char*, std::size_t>>{{"A_f", 4000}, {"coverage", 2},
                                                                                    {"fe_order", 3}}) {
    rc::write_mode_table(sample(), p);
    replace_root_attribute(p, name, count);
    const std::string e = read_error(p);
    EXPECT_NE(e.find(std::string("attribute '") + name + "' holds " + std::to_string(count) + " elements"),
              std::string::npos) << e;
  }
  // A number where an integer belongs (fe_order as one double) is refused by its class, not converted.
  rc::write_mode_table(sample(), p);
  replace_root_attribute(p, "fe_order", 1);
  EXPECT_NE(read_error(p).find("'fe_order' is not integer"), std::string::npos) << read_error(p);
  fs::remove(p);
}

TEST(ModeTable, NonFiniteModesAreRefusedAndTablesAreChecksummed) {
  const fs::path p = fs::temp_directory_path() / "rc_table_nan.h5";
  rc::write_mode_table(sample(), p);
  EXPECT_TRUE(rc::read_mode_table(p).checksummed);
  const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t set = H5Dopen2(f, "/modes/E", H5P_DEFAULT);
  const std::vector<double> E{std::nan(""), 0.01};
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, E.data());
  H5Dclose(set);
  H5Fclose(f);
  EXPECT_NE(read_error(p).find("non-finite"), std::string::npos) << read_error(p);
  fs::remove(p);
}

TEST(ModeTable, VolumeTensorsRoundTripAndAreChecked) {
  // A 3-D table (/volume, version 4): the per-mode Hermitian coupling tensors sort with their rows; a tensor that is
  // not Hermitian, or whose transverse trace is not the row's E, is refused.
  auto t = sample();
  t.converged.clear(); t.dlambda.clear(); t.dE.clear();
  auto& v = t.volume_cavity;
  v.centroid = {0.1, 0, 0};
  v.tilt = 0.5;
  v.inertia = {2.5, 0, 0, 0, 2.5, 0, 0, 0, 3.1};
  v.zhukovsky = {0.3, 0, 0, 0, 0.3, 0, 0, 0, 0};
  v.sum_rule = {2.2, 0, 0, 0, 2.2, 0, 0, 0, 3.1};
  v.geostrophic_re = v.geostrophic_im = std::vector<double>(9, 0.0);
  // H = c cᴴ with c = (√(E/2), i√(E/2), 0): H_xy = −i E/2.
  for (double E : t.E) {
    const double h = E / 2;
    const std::vector<double> re = {h, 0, 0, 0, h, 0, 0, 0, 0}, im = {0, -h, 0, h, 0, 0, 0, 0, 0};
    v.coupling_re.insert(v.coupling_re.end(), re.begin(), re.end());
    v.coupling_im.insert(v.coupling_im.end(), im.begin(), im.end());
  }
  t.sort_by_energy();
  fs::path p = fs::temp_directory_path() / "rc_mode_table_volume.h5";
  rc::write_mode_table(t, p);
  const auto r = rc::read_mode_table(p);
  ASSERT_TRUE(r.volume_cavity.present());
  EXPECT_DOUBLE_EQ(r.volume_cavity.tilt, 0.5);
  EXPECT_DOUBLE_EQ(r.volume_cavity.coupling_re[0], 2.0544 / 2);  // sorted by E with its row
  EXPECT_DOUBLE_EQ(r.volume_cavity.coupling_im[1], -2.0544 / 2);
  fs::remove(p);
  auto bad = t;
  bad.volume_cavity.coupling_im[3] = 0;  // H_yx no longer conj(H_xy)
  EXPECT_THROW(rc::write_mode_table(bad, p), std::runtime_error);
  bad = t;
  bad.volume_cavity.coupling_re[0] *= 2;  // H_xx + H_yy is not E
  EXPECT_THROW(rc::write_mode_table(bad, p), std::runtime_error);
  EXPECT_FALSE(fs::exists(p));
}

TEST(ModeTable, VolumeFreeSurfaceRoundTripsAndIsChecked) {
  // A partially filled 3-D tank's table (/volume_free_surface, docs/volume.md §8): each row's 5 × 5 coupling sorts with
  // its row (sorted by E: the unsorted second row comes first), its rotation block must be /volume's coupling, and the
  // sum rule's identity takes K from the surface parts' Gram matrix.
  auto t = sample();
  t.converged.clear(); t.dlambda.clear(); t.dE.clear();
  t.bands = {};
  auto& v = t.volume_cavity;
  v.centroid = {0.5, 0, 0};
  v.inertia = {2.5, 0, 0, 0, 2.5, 0, 0, 0, 3.1};
  v.geostrophic_re = v.geostrophic_im = std::vector<double>(9, 0.0);
  auto& f = t.volume_free_surface;
  f.fill = 0.5; f.radius = 1.5; f.axis = {-1.0, 0.0};
  f.gram_re = f.gram_im = f.geostrophic_re = f.geostrophic_im = f.surface_gram = std::vector<double>(25, 0.0);
  f.surface_gram[0] = f.surface_gram[6] = 0.4;  // K_xx = K_yy = 0.4: J_zh = A_f + K − sum_rule
  t.J_zh = t.A_f + 0.4 - t.sum_rule;
  std::vector<double> zhukovsky(9, 0.0), sum_rule(9, 0.0);
  v.zhukovsky = zhukovsky; v.sum_rule = sum_rule;
  for (std::size_t m = 0; m < t.E.size(); ++m) {
    const double h = t.E[m] / 2, tx = 0.1 * (m + 1);
    std::vector<double> re(25, 0.0), im(25, 0.0);
    re[0] = re[6] = h; im[1] = -h; im[5] = h;  // the rotation block as the filled sample's
    re[3] = re[15] = tx;                        // an offset coupling U_x·T_x, row-specific
    f.coupling_re.insert(f.coupling_re.end(), re.begin(), re.end());
    f.coupling_im.insert(f.coupling_im.end(), im.begin(), im.end());
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        v.coupling_re.push_back(re[5 * j + k]);
        v.coupling_im.push_back(im[5 * j + k]);
      }
  }
  t.sort_by_energy();
  fs::path p = fs::temp_directory_path() / "rc_mode_table_volume_fill.h5";
  rc::write_mode_table(t, p);
  const auto r = rc::read_mode_table(p);
  ASSERT_TRUE(r.volume_free_surface.present());
  EXPECT_TRUE(r.partially_filled());
  EXPECT_DOUBLE_EQ(r.volume_free_surface.radius, 1.5);
  EXPECT_DOUBLE_EQ(r.volume_free_surface.axis[0], -1.0);
  EXPECT_DOUBLE_EQ(r.volume_free_surface.coupling_re[3], 0.2);  // the heavier second row's, first after sorting
  EXPECT_DOUBLE_EQ(r.volume_free_surface.coupling_re[25 + 3], 0.1);
  fs::remove(p);
  auto bad = t;
  bad.volume_free_surface.coupling_re[6] *= 2;  // the rotation block no longer /volume's coupling
  EXPECT_THROW(rc::write_mode_table(bad, p), std::runtime_error);
  bad = t;
  bad.volume_free_surface.surface_gram[0] = 0.9;  // K changes: sum_rule = A_f + K − J_zh fails
  EXPECT_THROW(rc::write_mode_table(bad, p), std::runtime_error);
  bad = t;
  bad.volume_free_surface.gram_re.pop_back();
  EXPECT_THROW(rc::write_mode_table(bad, p), std::runtime_error);
  EXPECT_FALSE(fs::exists(p));
}
