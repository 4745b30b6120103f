#include "mode_table.hpp"

#include "hdf5_handle.hpp"
#include "mode_fields.hpp"
#include "printable_text.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <unistd.h>

namespace rc {
namespace {

void quiet_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void put_double(hid_t loc, const std::string& name, double v) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid attr(H5Acreate2(loc, name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &v) < 0)
    throw std::runtime_error("cannot write attribute " + name);
}

void put_long(hid_t loc, const std::string& name, long v) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid attr(H5Acreate2(loc, name.c_str(), H5T_NATIVE_LONG, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), H5T_NATIVE_LONG, &v) < 0)
    throw std::runtime_error("cannot write attribute " + name);
}

void put_string(hid_t loc, const std::string& name, const std::string& v) {
  Hid type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(v.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid attr(H5Acreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  std::string buf = v.empty() ? std::string(1, '\0') : v;
  if (!attr.ok() || H5Awrite(attr.get(), type.get(), buf.data()) < 0)
    throw std::runtime_error("cannot write attribute " + name);
}

template <class T>
void put_vector(hid_t loc, const std::string& name, const std::vector<T>& v, hid_t mem_type) {
  hsize_t n = v.size();
  Hid space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  Hid set(H5Dcreate2(loc, name.c_str(), mem_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.ok() || (n > 0 && H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0))
    throw std::runtime_error("cannot write dataset " + name);
}

// A scalar string dataset (a section file's text can pass the 64 KiB limit of an attribute).
void put_text(hid_t loc, const std::string& name, const std::string& v) {
  Hid type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(v.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid set(H5Dcreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  std::string buf = v.empty() ? std::string(1, '\0') : v;
  if (!set.ok() || H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) < 0)
    throw std::runtime_error("cannot write dataset " + name);
}

bool has_attr(hid_t loc, const std::string& name) { return H5Aexists(loc, name.c_str()) > 0; }

// An attribute read into one value must hold exactly one element of the expected class: H5Aread writes every
// element the file's dataspace claims, so a corrupted or foreign table whose scalar holds 4000 numbers would overwrite
// the stack (found with AddressSanitizer).
void require_one(hid_t attr, const std::string& name, std::initializer_list<H5T_class_t> classes, const char* what) {
  Hid space(H5Aget_space(attr), H5Sclose);
  const hssize_t points = space.ok() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (points != 1)
    throw std::runtime_error("attribute '" + name + "' holds " + std::to_string(points) + " elements, not one " + what);
  Hid type(H5Aget_type(attr), H5Tclose);
  const H5T_class_t c = type.ok() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
  for (const H5T_class_t ok : classes)
    if (c == ok) return;
  throw std::runtime_error(std::string("attribute '") + name + "' is not " + what);
}

double get_double(hid_t loc, const std::string& name) {
  if (!has_attr(loc, name)) throw std::runtime_error("missing attribute '" + name + "'");
  Hid attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) throw std::runtime_error("attribute '" + name + "' cannot be opened");
  require_one(attr.get(), name, {H5T_FLOAT, H5T_INTEGER}, "number");
  double v = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v) < 0) throw std::runtime_error("attribute '" + name + "' is not a number");
  return v;
}

long get_long(hid_t loc, const std::string& name) {
  if (!has_attr(loc, name)) throw std::runtime_error("missing attribute '" + name + "'");
  Hid attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) throw std::runtime_error("attribute '" + name + "' cannot be opened");
  require_one(attr.get(), name, {H5T_INTEGER}, "integer");
  long v = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_LONG, &v) < 0) throw std::runtime_error("attribute '" + name + "' is not an integer");
  return v;
}

std::string get_string(hid_t loc, const std::string& name) {
  if (!has_attr(loc, name)) throw std::runtime_error("missing attribute '" + name + "'");
  Hid attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) throw std::runtime_error("attribute '" + name + "' cannot be opened");
  require_one(attr.get(), name, {H5T_STRING}, "string");
  Hid ftype(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tis_variable_str(ftype.get()) > 0) {
    Hid mtype(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mtype.get(), H5T_VARIABLE);
    char* p = nullptr;
    if (H5Aread(attr.get(), mtype.get(), &p) < 0) throw std::runtime_error("cannot read attribute '" + name + "'");
    std::string s = p ? p : "";
    free(p);
    return printable_text(s);
  }
  std::size_t n = H5Tget_size(ftype.get());
  if (n > 64u << 10) throw std::runtime_error("attribute '" + name + "' claims a string of " + std::to_string(n) + " bytes");
  std::string buf(n + 1, '\0');
  Hid mtype(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mtype.get(), n + 1);
  if (H5Aread(attr.get(), mtype.get(), buf.data()) < 0) throw std::runtime_error("cannot read attribute '" + name + "'");
  return printable_text(buf.c_str());  // a corrupted byte prints as \xNN, never raw
}

template <class... Args>
std::string formatted(const char* format, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

std::string get_text(hid_t loc, const std::string& name) {
  if (H5Lexists(loc, name.c_str(), H5P_DEFAULT) <= 0) return {};
  Hid set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  Hid ftype(H5Dget_type(set.get()), H5Tclose);
  if (!set.ok() || H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) > 0)
    throw std::runtime_error("dataset '" + name + "' is not a fixed-length string");
  const std::size_t n = H5Tget_size(ftype.get());
  Hid file(H5Iget_file_id(loc), H5Fclose);
  hsize_t file_size = 0;
  if (!file.ok() || H5Fget_filesize(file.get(), &file_size) < 0 || n > 16 * file_size + 1024)
    throw std::runtime_error("dataset '" + name + "' claims " + std::to_string(n) + " bytes, more than the file holds");
  std::string buf(n + 1, '\0');
  Hid mtype(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mtype.get(), n + 1);
  if (H5Dread(set.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) < 0)
    throw std::runtime_error("cannot read dataset '" + name + "'");
  return printable_text(buf.c_str());
}

template <class T>
std::vector<T> get_vector(hid_t loc, const std::string& name, hid_t mem_type, bool required) {
  if (H5Lexists(loc, name.c_str(), H5P_DEFAULT) <= 0) {
    if (required) throw std::runtime_error("missing dataset '" + name + "'");
    return {};
  }
  Hid set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  Hid space(H5Dget_space(set.get()), H5Sclose);
  if (!set.ok() || H5Sget_simple_extent_ndims(space.get()) != 1)
    throw std::runtime_error("dataset '" + name + "' is not one-dimensional");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  // A corrupted size must not become a huge allocation: a dataset cannot hold more than its file (uncompressed,
  // as written here; 16x leaves room for a compressed copy).
  Hid file(H5Iget_file_id(loc), H5Fclose);
  hsize_t file_size = 0;
  if (!file.ok() || H5Fget_filesize(file.get(), &file_size) < 0 || n > (16 * file_size) / sizeof(T) + 1024)
    throw std::runtime_error("dataset '" + name + "' claims " + std::to_string(n) + " entries, more than the file holds");
  std::vector<T> v(n);
  if (n > 0 && H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw std::runtime_error("cannot read dataset '" + name + "'");
  return v;
}

// The meridian free surface's attributes, and its columns only where it is present.
void validate_free_surface(const ModeTable& t) {
  if (t.free_surface.present()) {
    const ModeTable::FreeSurface& f = t.free_surface;
    for (double x : {f.fill, f.radius, f.K0, f.K1, f.K2, f.J1, f.J2})
      if (!std::isfinite(x)) throw std::runtime_error("/free_surface holds a non-finite attribute");
    if (!(f.fill > 0 && f.fill < 1) || !(f.K0 > 0) || !(f.K2 >= 0) || !(f.J2 >= 0))
      throw std::runtime_error("/free_surface: fill outside (0, 1), or K0, K2, J2 not positive");
  } else if (!t.free_surface.t.empty()) {
    throw std::runtime_error("/free_surface/t in a table without a free surface");
  }
  if (!t.viscous() && !t.free_surface.t_imag.empty())
    throw std::runtime_error("/free_surface/t_imag in a table whose ekman is not positive");
}

// /fit_decay: a profile of Im R's error over the window of a table that has fit_decay_error, s increasing inside it.
void validate_fit_decay_profile(const ModeTable& t) {
  const auto& s = t.fit_decay_s;
  const auto& e = t.fit_decay_profile;
  if (s.empty() && e.empty()) return;
  if (s.size() != e.size() || s.size() < 2 || t.fit_decay_error < 0)
    throw std::runtime_error("/fit_decay: s and error differ in length, hold fewer than 2 points, or the table has no "
                             "fit_decay_error");
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!std::isfinite(s[i]) || !(e[i] >= 0) || !std::isfinite(e[i]) || (i > 0 && !(s[i] > s[i - 1])) ||
        s[i] < t.fit_lo - 1e-12 || s[i] > t.fit_hi + 1e-12)
      throw std::runtime_error("/fit_decay: s not increasing inside [fit_lo, fit_hi], or an error not finite and >= 0");
}

// The viscous columns and attributes: only in a viscous table, the response window and its errors finite.
void validate_viscous_attributes(const ModeTable& t) {
  if (!t.viscous() && !(t.decay.empty() && t.E_imag.empty() && t.a_imag.empty()))
    throw std::runtime_error("/modes/decay, E_imag or a_imag in a table whose ekman is not positive");
  if (!std::isfinite(t.ekman) || t.ekman < 0) throw std::runtime_error("root attribute ekman must be >= 0 and finite");
  if (!std::isfinite(t.fit_lo) || !std::isfinite(t.fit_hi) || !(t.fit_error >= 0) || !std::isfinite(t.fit_error) ||
      t.fit_hi < t.fit_lo || (t.response_fit() && !t.viscous()))
    throw std::runtime_error("root attributes fit_lo, fit_hi, fit_error: not a window with a finite error of a "
                             "viscous table");
  if (!std::isfinite(t.fit_decay_error) || (t.fit_decay_error >= 0 && !t.response_fit()))
    throw std::runtime_error("root attribute fit_decay_error: not a finite error of a response table");
  validate_fit_decay_profile(t);
  for (double d : t.decay)
    if (d < 0) throw std::runtime_error("/modes/decay holds a negative value (a growing viscous mode)");
}

// /galerkin: four n × n matrices of a damped-mode table, Hermitian (Gram with a positive diagonal).
void validate_galerkin(const ModeTable& t) {
  const auto& g = t.galerkin;
  if (g.empty() && g.gram_im.empty() && g.viscous_re.empty() && g.viscous_im.empty()) return;
  const std::size_t n = t.E.size();
  const bool coupled = !g.coupling_re.empty() || !g.coupling_im.empty();
  if (!t.viscous() || (t.response_fit() && !coupled))
    throw std::runtime_error("/galerkin in a table that is neither a damped-mode table nor a Galerkin response table");
  if (coupled && (g.coupling_re.size() != n || g.coupling_im.size() != n))
    throw std::runtime_error("/galerkin/coupling_re and coupling_im must hold one entry per row");
  for (const auto* v : {&g.gram_re, &g.gram_im, &g.viscous_re, &g.viscous_im}) {
    if (v->size() != n * n)
      throw std::runtime_error("/galerkin holds a matrix of " + std::to_string(v->size()) + " entries for " +
                               std::to_string(n) + " rows (n x n expected)");
    for (double x : *v)
      if (!std::isfinite(x)) throw std::runtime_error("/galerkin holds a non-finite value");
  }
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, g.gram_re[i * n + i]);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(g.gram_re[i * n + i] > 0)) throw std::runtime_error("/galerkin/gram has a diagonal entry that is not positive");
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t ij = i * n + j, ji = j * n + i;
      if (std::abs(g.gram_re[ij] - g.gram_re[ji]) + std::abs(g.gram_im[ij] + g.gram_im[ji]) > 1e-9 * scale)
        throw std::runtime_error("/galerkin/gram is not Hermitian");
    }
  }
}

// /free_surface: the partially filled tank's attributes and its per-mode offset coupling t.
void write_free_surface(hid_t root, const ModeTable::FreeSurface& f) {
  Hid g(H5Gcreate2(root, "free_surface", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  put_double(g.get(), "fill", f.fill);
  put_double(g.get(), "radius", f.radius);
  put_double(g.get(), "K0", f.K0);
  put_double(g.get(), "K1", f.K1);
  put_double(g.get(), "K2", f.K2);
  put_double(g.get(), "J1", f.J1);
  put_double(g.get(), "J2", f.J2);
  put_vector(g.get(), "t", f.t, H5T_NATIVE_DOUBLE);
  if (!f.t_imag.empty()) put_vector(g.get(), "t_imag", f.t_imag, H5T_NATIVE_DOUBLE);
}

ModeTable::FreeSurface read_free_surface(hid_t root) {
  Hid g(H5Gopen2(root, "free_surface", H5P_DEFAULT), H5Gclose);
  if (!g.ok()) throw std::runtime_error("cannot open /free_surface");
  ModeTable::FreeSurface f;
  f.fill = get_double(g.get(), "fill");
  f.radius = get_double(g.get(), "radius");
  if (!(f.radius > 0)) throw std::runtime_error("/free_surface: radius must be positive");
  f.K0 = get_double(g.get(), "K0");
  f.K1 = get_double(g.get(), "K1");
  f.K2 = get_double(g.get(), "K2");
  f.J1 = get_double(g.get(), "J1");
  f.J2 = get_double(g.get(), "J2");
  f.t = get_vector<double>(g.get(), "t", H5T_NATIVE_DOUBLE, true);
  if (H5Lexists(g.get(), "t_imag", H5P_DEFAULT) > 0) f.t_imag = get_vector<double>(g.get(), "t_imag", H5T_NATIVE_DOUBLE, true);
  return f;
}

// /volume_free_surface: a partially filled 3-D tank's surface, axis and five-direction couplings.
constexpr std::pair<const char*, std::vector<double> ModeTable::VolumeFreeSurface::*> kVolumeSurfaceSets[] = {
    {"axis", &ModeTable::VolumeFreeSurface::axis},
    {"coupling_re", &ModeTable::VolumeFreeSurface::coupling_re},
    {"coupling_im", &ModeTable::VolumeFreeSurface::coupling_im},
    {"gram_re", &ModeTable::VolumeFreeSurface::gram_re},
    {"gram_im", &ModeTable::VolumeFreeSurface::gram_im},
    {"geostrophic_re", &ModeTable::VolumeFreeSurface::geostrophic_re},
    {"geostrophic_im", &ModeTable::VolumeFreeSurface::geostrophic_im},
    {"surface_gram", &ModeTable::VolumeFreeSurface::surface_gram}};

void write_volume_free_surface(hid_t root, const ModeTable::VolumeFreeSurface& f) {
  Hid g(H5Gcreate2(root, "volume_free_surface", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  put_double(g.get(), "fill", f.fill);
  put_double(g.get(), "radius", f.radius);
  for (const auto& [name, member] : kVolumeSurfaceSets) put_vector(g.get(), name, f.*member, H5T_NATIVE_DOUBLE);
}

ModeTable::VolumeFreeSurface read_volume_free_surface(hid_t root) {
  Hid g(H5Gopen2(root, "volume_free_surface", H5P_DEFAULT), H5Gclose);
  if (!g.ok()) throw std::runtime_error("cannot open /volume_free_surface");
  ModeTable::VolumeFreeSurface f;
  f.fill = get_double(g.get(), "fill");
  f.radius = get_double(g.get(), "radius");
  if (!(f.radius > 0)) throw std::runtime_error("/volume_free_surface: radius must be positive");
  for (const auto& [name, member] : kVolumeSurfaceSets) f.*member = get_vector<double>(g.get(), name, H5T_NATIVE_DOUBLE, true);
  return f;
}

void validate_volume_free_surface(const ModeTable& t) {
  const auto& f = t.volume_free_surface;
  if (!f.present()) {
    if (!f.coupling_re.empty()) throw std::runtime_error("/volume_free_surface/coupling_re in a table without it");
    return;
  }
  if (!t.volume_cavity.present() || t.free_surface.present())
    throw std::runtime_error("/volume_free_surface needs /volume and no axisymmetric /free_surface");
  if (!(f.fill > 0 && f.fill < 1) || !std::isfinite(f.radius)) throw std::runtime_error("/volume_free_surface: fill outside (0, 1)");
  const std::size_t n = t.E.size();
  if (f.axis.size() != 2 || f.coupling_re.size() != 25 * n || f.coupling_im.size() != 25 * n || f.gram_re.size() != 25 ||
      f.gram_im.size() != 25 || f.geostrophic_re.size() != 25 || f.geostrophic_im.size() != 25 || f.surface_gram.size() != 25)
    throw std::runtime_error("/volume_free_surface: a set does not hold 2, 25 or 25 per mode entries");
  for (const auto& [name, member] : kVolumeSurfaceSets)
    for (double x : f.*member)
      if (!std::isfinite(x)) throw std::runtime_error(std::string("/volume_free_surface/") + name + " holds a non-finite value");
  // Each row's rotation block is /volume's coupling.
  for (std::size_t m = 0; m < n; ++m)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double a = f.coupling_re[25 * m + 5 * j + k], b = t.volume_cavity.coupling_re[9 * m + 3 * j + k];
        if (std::abs(a - b) > 1e-12 * (1 + std::abs(t.E[m])))
          throw std::runtime_error("/volume_free_surface: row " + std::to_string(m + 1) + "'s rotation block is not /volume's coupling");
      }
}

// /volume: a 3-D cavity's tensors and per-mode coupling tensors.
void write_volume(hid_t root, const ModeTable::Volume& v) {
  Hid g(H5Gcreate2(root, "volume", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  put_double(g.get(), "tilt", v.tilt);
  for (const auto& [name, data] : {std::pair{"centroid", &v.centroid}, {"inertia", &v.inertia},
                                   {"zhukovsky", &v.zhukovsky}, {"sum_rule", &v.sum_rule},
                                   {"geostrophic_re", &v.geostrophic_re}, {"geostrophic_im", &v.geostrophic_im},
                                   {"coupling_re", &v.coupling_re}, {"coupling_im", &v.coupling_im}})
    put_vector(g.get(), name, *data, H5T_NATIVE_DOUBLE);
  if (!v.band_lambda.empty())
    for (const auto& [name, data] : {std::pair{"band_coupling_re", &v.band_coupling_re},
                                     {"band_coupling_im", &v.band_coupling_im}, {"band_lambda", &v.band_lambda}})
      put_vector(g.get(), name, *data, H5T_NATIVE_DOUBLE);
}

ModeTable::Volume read_volume(hid_t root) {
  Hid g(H5Gopen2(root, "volume", H5P_DEFAULT), H5Gclose);
  if (!g.ok()) throw std::runtime_error("cannot open /volume");
  ModeTable::Volume v;
  v.tilt = get_double(g.get(), "tilt");
  for (const auto& [name, data] : {std::pair{"centroid", &v.centroid}, {"inertia", &v.inertia},
                                   {"zhukovsky", &v.zhukovsky}, {"sum_rule", &v.sum_rule},
                                   {"geostrophic_re", &v.geostrophic_re}, {"geostrophic_im", &v.geostrophic_im},
                                   {"coupling_re", &v.coupling_re}, {"coupling_im", &v.coupling_im}})
    *data = get_vector<double>(g.get(), name, H5T_NATIVE_DOUBLE, true);
  for (const auto& [name, data] : {std::pair{"band_coupling_re", &v.band_coupling_re},  // tables before them lack them
                                   {"band_coupling_im", &v.band_coupling_im}, {"band_lambda", &v.band_lambda}})
    *data = get_vector<double>(g.get(), name, H5T_NATIVE_DOUBLE, false);
  return v;
}

// /volume: sizes, finiteness, Hermitian coupling tensors whose transverse trace is the row's E.
void validate_volume(const ModeTable& t) {
  const auto& v = t.volume_cavity;
  if (!v.present()) {
    if (!v.coupling_re.empty()) throw std::runtime_error("/volume/coupling_re in a table without /volume");
    return;
  }
  const std::size_t n = t.E.size();
  if (v.centroid.size() != 3 || v.inertia.size() != 9 || v.zhukovsky.size() != 9 || v.sum_rule.size() != 9 ||
      v.geostrophic_re.size() != 9 || v.geostrophic_im.size() != 9 || v.coupling_re.size() != 9 * n ||
      v.coupling_im.size() != 9 * n)
    throw std::runtime_error("/volume: a tensor does not hold 9 entries (per mode for the couplings)");
  const std::size_t nb = v.band_lambda.size();
  if ((nb > 0 && nb != t.bands.size()) || v.band_coupling_re.size() != 9 * nb || v.band_coupling_im.size() != 9 * nb)
    throw std::runtime_error("/volume: the band couplings do not hold 9 entries per band of /bands");
  for (const auto* d : {&v.centroid, &v.inertia, &v.zhukovsky, &v.sum_rule, &v.geostrophic_re, &v.geostrophic_im,
                        &v.coupling_re, &v.coupling_im, &v.band_coupling_re, &v.band_coupling_im, &v.band_lambda})
    for (double x : *d)
      if (!std::isfinite(x)) throw std::runtime_error("/volume holds a non-finite value");
  if (t.free_surface.present()) throw std::runtime_error("/volume in a partially filled table");
  if (t.viscous() && nb > 0) throw std::runtime_error("/volume: band couplings in a viscous table (they are the ideal "
                                                      "fluid's measure)");
  for (std::size_t m = 0; m < n; ++m) {
    const double* re = &v.coupling_re[9 * m];
    const double* im = &v.coupling_im[9 * m];
    const double scale = std::max(std::hypot(re[0] + re[4] + re[8], im[0] + im[4] + im[8]), 1e-300);
    // An ideal mode's H = c cᴴ is Hermitian; a damped mode's (x_R, x_L its right and left vectors) is the rank-one
    // product of two different vectors (docs/volume.md §7), with the complex E + i·E_imag as its transverse trace.
    if (!t.viscous())
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          if (std::abs(re[3 * j + k] - re[3 * k + j]) + std::abs(im[3 * j + k] + im[3 * k + j]) > 1e-9 * scale)
            throw std::runtime_error("/volume: the coupling tensor of mode " + std::to_string(m) + " is not Hermitian");
    const std::complex<double> E_c(t.E[m], t.viscous() ? t.E_imag[m] : 0.0), trace(re[0] + re[4], im[0] + im[4]);
    if (std::abs(trace - E_c) > 1e-9 * std::max(std::abs(E_c), scale))
      throw std::runtime_error("/volume: mode " + std::to_string(m) + "'s E is not H_xx + H_yy");
  }
}

// The root attributes (docs/physics.md §4).
void write_root_attributes(hid_t root, const ModeTable& t) {
  put_string(root, "format", kModeTableFormat);
  put_long(root, "version", t.volume_cavity.present() ? kVolumeTableVersion
                            : t.free_surface.present() ? kFreeSurfaceTableVersion : kModeTableVersion);
  put_string(root, "shape", t.shape);
  std::string dims;
  for (const auto& [k, v] : t.dimensions) {
    put_double(root, k, v);
    dims += (dims.empty() ? "" : ",") + k;
  }
  put_string(root, "dimension_names", dims);
  put_long(root, "fe_order", t.fe_order);
  put_double(root, "mesh_h", t.mesh_h);
  if (t.mesh_h_radial > 0) put_double(root, "mesh_h_radial", t.mesh_h_radial);
  put_long(root, "ndof", t.ndof);
  put_long(root, "m", t.m);
  put_double(root, "volume", t.volume);
  put_double(root, "centroid_z", t.centroid_z);
  put_double(root, "A_f", t.A_f);
  put_double(root, "C_f", t.C_f);
  put_double(root, "J_zh", t.J_zh);
  put_double(root, "sum_rule", t.sum_rule);
  put_double(root, "coverage", t.coverage);
  put_string(root, "solver", t.solver);
  put_double(root, "tolerance", t.tolerance);
  put_double(root, "wall_seconds", t.wall_seconds);
  put_string(root, "normalisation", t.normalisation);
  put_double(root, "ekman", t.ekman);
  if (t.mesh_h_wall > 0) put_double(root, "mesh_h_wall", t.mesh_h_wall);
  if (t.mesh_h_near_wall > 0) put_double(root, "mesh_h_near_wall", t.mesh_h_near_wall);
  if (t.response_fit()) {
    put_double(root, "fit_lo", t.fit_lo);
    put_double(root, "fit_hi", t.fit_hi);
    put_double(root, "fit_error", t.fit_error);
    if (t.fit_decay_error >= 0) put_double(root, "fit_decay_error", t.fit_decay_error);
  }
  if (!t.convergence_reference.empty()) {
    put_string(root, "convergence_reference", t.convergence_reference);
    put_double(root, "convergence_tolerance", t.convergence_tolerance);
  }
}

// /modes: one entry per row.
void write_modes_group(hid_t root, const ModeTable& t) {
  Hid modes(H5Gcreate2(root, "modes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  put_vector(modes.get(), "kappa", t.kappa, H5T_NATIVE_DOUBLE);
  put_vector(modes.get(), "lambda", t.lambda, H5T_NATIVE_DOUBLE);
  put_vector(modes.get(), "E", t.E, H5T_NATIVE_DOUBLE);
  put_vector(modes.get(), "a", t.a, H5T_NATIVE_DOUBLE);
  put_vector(modes.get(), "N2", t.N2, H5T_NATIVE_DOUBLE);
  put_vector(modes.get(), "residual", t.residual, H5T_NATIVE_DOUBLE);
  if (!t.spread.empty()) put_vector(modes.get(), "spread", t.spread, H5T_NATIVE_DOUBLE);
  if (!t.members.empty()) put_vector(modes.get(), "members", t.members, H5T_NATIVE_INT);
  if (!t.dlambda.empty()) put_vector(modes.get(), "dlambda", t.dlambda, H5T_NATIVE_DOUBLE);
  if (!t.dE.empty()) put_vector(modes.get(), "dE", t.dE, H5T_NATIVE_DOUBLE);
  if (!t.converged.empty()) put_vector(modes.get(), "converged", t.converged, H5T_NATIVE_INT);
  if (t.viscous()) {
    put_vector(modes.get(), "decay", t.decay, H5T_NATIVE_DOUBLE);
    put_vector(modes.get(), "E_imag", t.E_imag, H5T_NATIVE_DOUBLE);
    put_vector(modes.get(), "a_imag", t.a_imag, H5T_NATIVE_DOUBLE);
  }
}

// /bands, /galerkin, /fit_decay, /free_surface, /provenance where the table has them.
void write_optional_groups(hid_t root, const ModeTable& t) {
  if (t.bands.size() > 0) {
    Hid bands(H5Gcreate2(root, "bands", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    put_vector(bands.get(), "lo", t.bands.lo, H5T_NATIVE_DOUBLE);
    put_vector(bands.get(), "hi", t.bands.hi, H5T_NATIVE_DOUBLE);
    put_vector(bands.get(), "E", t.bands.E, H5T_NATIVE_DOUBLE);
    put_vector(bands.get(), "lambda_mean", t.bands.lambda_mean, H5T_NATIVE_DOUBLE);
  }
  if (t.has_galerkin()) {
    Hid gal(H5Gcreate2(root, "galerkin", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    put_vector(gal.get(), "gram_re", t.galerkin.gram_re, H5T_NATIVE_DOUBLE);
    put_vector(gal.get(), "gram_im", t.galerkin.gram_im, H5T_NATIVE_DOUBLE);
    put_vector(gal.get(), "viscous_re", t.galerkin.viscous_re, H5T_NATIVE_DOUBLE);
    put_vector(gal.get(), "viscous_im", t.galerkin.viscous_im, H5T_NATIVE_DOUBLE);
    put_double(gal.get(), "dissipation_mismatch", t.galerkin.dissipation_mismatch);
    if (!t.galerkin.coupling_re.empty()) {
      put_vector(gal.get(), "coupling_re", t.galerkin.coupling_re, H5T_NATIVE_DOUBLE);
      put_vector(gal.get(), "coupling_im", t.galerkin.coupling_im, H5T_NATIVE_DOUBLE);
    }
  }
  if (!t.fit_decay_s.empty()) {
    Hid fit(H5Gcreate2(root, "fit_decay", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    put_vector(fit.get(), "s", t.fit_decay_s, H5T_NATIVE_DOUBLE);
    put_vector(fit.get(), "error", t.fit_decay_profile, H5T_NATIVE_DOUBLE);
  }
  if (t.free_surface.present()) write_free_surface(root, t.free_surface);
  if (t.volume_free_surface.present()) write_volume_free_surface(root, t.volume_free_surface);
  if (t.volume_cavity.present()) write_volume(root, t.volume_cavity);
  if (!t.geometry_source.empty() || !t.command_line.empty()) {
    Hid prov(H5Gcreate2(root, "provenance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    put_text(prov.get(), "geometry_source", t.geometry_source);
    put_text(prov.get(), "geometry_text", t.geometry_text);
    put_text(prov.get(), "command_line", t.command_line);
  }
}

// The root attributes (docs/physics.md §4); every one checked for its class and for one element (get_double, ...).
void read_root_attributes(hid_t root, ModeTable& t) {
  if (get_long(root, "version") > kVolumeTableVersion)
    throw std::runtime_error("mode table version is newer than this program understands");
  t.shape = get_string(root, "shape");
  if (has_attr(root, "dimension_names")) {
    std::string names = get_string(root, "dimension_names");
    std::size_t pos = 0;
    while (pos < names.size()) {
      std::size_t end = names.find(',', pos);
      if (end == std::string::npos) end = names.size();
      std::string k = names.substr(pos, end - pos);
      if (!k.empty()) t.dimensions[k] = get_double(root, k);
      pos = end + 1;
    }
  }
  t.fe_order = static_cast<int>(get_long(root, "fe_order"));
  t.mesh_h = get_double(root, "mesh_h");
  if (has_attr(root, "mesh_h_radial")) t.mesh_h_radial = get_double(root, "mesh_h_radial");
  t.ndof = get_long(root, "ndof");
  t.m = static_cast<int>(get_long(root, "m"));
  t.volume = get_double(root, "volume");
  t.centroid_z = get_double(root, "centroid_z");
  t.A_f = get_double(root, "A_f");
  t.C_f = get_double(root, "C_f");
  t.J_zh = get_double(root, "J_zh");
  t.sum_rule = get_double(root, "sum_rule");
  t.coverage = get_double(root, "coverage");
  t.solver = get_string(root, "solver");
  t.tolerance = get_double(root, "tolerance");
  t.wall_seconds = get_double(root, "wall_seconds");
  if (has_attr(root, "normalisation")) t.normalisation = get_string(root, "normalisation");
  if (has_attr(root, "ekman")) t.ekman = get_double(root, "ekman");
  if (has_attr(root, "mesh_h_wall")) t.mesh_h_wall = get_double(root, "mesh_h_wall");
  if (has_attr(root, "mesh_h_near_wall")) t.mesh_h_near_wall = get_double(root, "mesh_h_near_wall");
  if (has_attr(root, "fit_lo") || has_attr(root, "fit_hi") || has_attr(root, "fit_error")) {
    t.fit_lo = get_double(root, "fit_lo");
    t.fit_hi = get_double(root, "fit_hi");
    t.fit_error = get_double(root, "fit_error");
  }
  if (has_attr(root, "fit_decay_error")) t.fit_decay_error = get_double(root, "fit_decay_error");
  if (has_attr(root, "convergence_reference")) {
    t.convergence_reference = get_string(root, "convergence_reference");
    t.convergence_tolerance = get_double(root, "convergence_tolerance");
  }
}

// /modes: the required columns and the optional ones.
void read_modes_group(hid_t root, ModeTable& t) {
  if (H5Lexists(root, "modes", H5P_DEFAULT) <= 0) throw std::runtime_error("missing group /modes");
  Hid modes(H5Gopen2(root, "modes", H5P_DEFAULT), H5Gclose);
  t.kappa = get_vector<double>(modes.get(), "kappa", H5T_NATIVE_DOUBLE, true);
  t.lambda = get_vector<double>(modes.get(), "lambda", H5T_NATIVE_DOUBLE, true);
  t.E = get_vector<double>(modes.get(), "E", H5T_NATIVE_DOUBLE, true);
  t.a = get_vector<double>(modes.get(), "a", H5T_NATIVE_DOUBLE, true);
  t.N2 = get_vector<double>(modes.get(), "N2", H5T_NATIVE_DOUBLE, true);
  t.residual = get_vector<double>(modes.get(), "residual", H5T_NATIVE_DOUBLE, true);
  t.spread = get_vector<double>(modes.get(), "spread", H5T_NATIVE_DOUBLE, false);
  t.members = get_vector<int>(modes.get(), "members", H5T_NATIVE_INT, false);
  t.dlambda = get_vector<double>(modes.get(), "dlambda", H5T_NATIVE_DOUBLE, false);
  t.dE = get_vector<double>(modes.get(), "dE", H5T_NATIVE_DOUBLE, false);
  t.converged = get_vector<int>(modes.get(), "converged", H5T_NATIVE_INT, false);
  t.decay = get_vector<double>(modes.get(), "decay", H5T_NATIVE_DOUBLE, false);
  t.E_imag = get_vector<double>(modes.get(), "E_imag", H5T_NATIVE_DOUBLE, false);
  t.a_imag = get_vector<double>(modes.get(), "a_imag", H5T_NATIVE_DOUBLE, false);
}

// /bands, /galerkin, /fit_decay, /free_surface, /provenance where the file has them.
void read_optional_groups(hid_t root, ModeTable& t) {
  if (H5Lexists(root, "bands", H5P_DEFAULT) > 0) {
    Hid bands(H5Gopen2(root, "bands", H5P_DEFAULT), H5Gclose);
    t.bands.lo = get_vector<double>(bands.get(), "lo", H5T_NATIVE_DOUBLE, true);
    t.bands.hi = get_vector<double>(bands.get(), "hi", H5T_NATIVE_DOUBLE, true);
    t.bands.E = get_vector<double>(bands.get(), "E", H5T_NATIVE_DOUBLE, true);
    t.bands.lambda_mean = get_vector<double>(bands.get(), "lambda_mean", H5T_NATIVE_DOUBLE, true);
  }
  if (H5Lexists(root, "galerkin", H5P_DEFAULT) > 0) {
    Hid gal(H5Gopen2(root, "galerkin", H5P_DEFAULT), H5Gclose);
    t.galerkin.gram_re = get_vector<double>(gal.get(), "gram_re", H5T_NATIVE_DOUBLE, true);
    t.galerkin.gram_im = get_vector<double>(gal.get(), "gram_im", H5T_NATIVE_DOUBLE, true);
    t.galerkin.viscous_re = get_vector<double>(gal.get(), "viscous_re", H5T_NATIVE_DOUBLE, true);
    t.galerkin.viscous_im = get_vector<double>(gal.get(), "viscous_im", H5T_NATIVE_DOUBLE, true);
    t.galerkin.coupling_re = get_vector<double>(gal.get(), "coupling_re", H5T_NATIVE_DOUBLE, false);
    t.galerkin.coupling_im = get_vector<double>(gal.get(), "coupling_im", H5T_NATIVE_DOUBLE, false);
    if (has_attr(gal.get(), "dissipation_mismatch"))
      t.galerkin.dissipation_mismatch = get_double(gal.get(), "dissipation_mismatch");
  }
  if (H5Lexists(root, "fit_decay", H5P_DEFAULT) > 0) {
    Hid fit(H5Gopen2(root, "fit_decay", H5P_DEFAULT), H5Gclose);
    t.fit_decay_s = get_vector<double>(fit.get(), "s", H5T_NATIVE_DOUBLE, true);
    t.fit_decay_profile = get_vector<double>(fit.get(), "error", H5T_NATIVE_DOUBLE, true);
  }
  if (H5Lexists(root, "free_surface", H5P_DEFAULT) > 0) t.free_surface = read_free_surface(root);
  if (H5Lexists(root, "volume_free_surface", H5P_DEFAULT) > 0) t.volume_free_surface = read_volume_free_surface(root);
  if (H5Lexists(root, "volume", H5P_DEFAULT) > 0) t.volume_cavity = read_volume(root);
  if (H5Lexists(root, "provenance", H5P_DEFAULT) > 0) {
    Hid prov(H5Gopen2(root, "provenance", H5P_DEFAULT), H5Gclose);
    t.geometry_source = get_text(prov.get(), "geometry_source");
    t.geometry_text = get_text(prov.get(), "geometry_text");
    t.command_line = get_text(prov.get(), "command_line");
  }
}

}  // namespace

void ModeTable::validate() const {
  const std::size_t n = E.size();
  auto check = [&](const std::vector<double>& v, const char* name, bool optional) {
    if (optional && v.empty()) return;
    if (v.size() != n) throw std::runtime_error(std::string("/modes/") + name + " has " + std::to_string(v.size()) +
                                                " entries, /modes/E has " + std::to_string(n));
    for (double x : v)
      if (!std::isfinite(x)) throw std::runtime_error(std::string("/modes/") + name + " holds a non-finite value");
  };
  check(kappa, "kappa", false);
  check(lambda, "lambda", false);
  check(a, "a", false);
  check(N2, "N2", false);
  check(residual, "residual", false);
  check(spread, "spread", true);
  check(dlambda, "dlambda", true);
  check(dE, "dE", true);
  check(decay, "decay", !viscous());
  check(E_imag, "E_imag", !viscous());
  check(a_imag, "a_imag", !viscous());
  check(free_surface.t, "t (/free_surface)", !free_surface.present());
  check(free_surface.t_imag, "t_imag (/free_surface)", !(free_surface.present() && viscous()));
  validate_free_surface(*this);
  validate_viscous_attributes(*this);
  if (!members.empty() && members.size() != n) throw std::runtime_error("/modes/members has the wrong length");
  if (!converged.empty() && converged.size() != n) throw std::runtime_error("/modes/converged has the wrong length");
  const std::size_t nb = bands.E.size();
  if (bands.lo.size() != nb || bands.hi.size() != nb || bands.lambda_mean.size() != nb)
    throw std::runtime_error("/bands datasets differ in length");
  validate_galerkin(*this);
  validate_volume(*this);
  validate_volume_free_surface(*this);
  for (double x : {volume, A_f, C_f, J_zh, sum_rule, coverage})
    if (!std::isfinite(x)) throw std::runtime_error("a root attribute holds a non-finite value");
  for (const auto* column : {&kappa, &lambda, &E, &a, &N2, &decay, &E_imag, &a_imag})
    for (double x : *column)
      if (!std::isfinite(x)) throw std::runtime_error("/modes holds a non-finite value (NaN or infinity)");
  if (!viscous())  // a viscous residue's real part is the ideal E only in the limit
    for (double e : E)
      if (e < 0) throw std::runtime_error("/modes/E holds a negative value");
  check_identities();
}

// The table's own identities (docs/physics.md §2), so that an edited or corrupted table is refused on reading
// with the identity it breaks rather than giving a chain nonsense.
void ModeTable::check_identities() const {
  const auto fail = [](const std::string& what) { throw std::runtime_error("table identity fails: " + what); };
  const bool some = !dlambda.empty() || !dE.empty() || !converged.empty();
  if (some && (dlambda.empty() || dE.empty() || converged.empty()))
    fail("/modes/dlambda, dE and converged come together (the convergence check), one of them is missing");
  if (!(volume > 0)) fail("volume > 0");
  // A 3-D partial fill's: the transverse half-trace of the surface parts' Gram matrix, K about P0.
  const auto& vs = volume_free_surface.surface_gram;
  const double K2 = free_surface.present() ? free_surface.K2 : volume_free_surface.present() ? 0.5 * (vs[0] + vs[6]) : 0.0;
  if (std::abs(sum_rule - (A_f + K2 - J_zh)) > 1e-9 * std::max({std::abs(A_f), std::abs(J_zh), 1e-300}))
    fail(formatted(partially_filled() ? "sum_rule = A_f + K2 - J_zh (%.12g against %.12g)"
                                          : "sum_rule = A_f - J_zh (%.12g against %.12g)", sum_rule, A_f + K2 - J_zh));
  const double tiny = 1e-12 * std::max(std::abs(sum_rule), 1e-300);
  for (std::size_t i = 0; i < E.size(); ++i) {
    // A 3-D viscous response table's purely damped rows (the fluid's spin-up, docs/volume.md §7) have no frequency
    // and no wavelength: lambda = 0, kappa = 0, decay > 0.
    const bool spin_up = lambda[i] == 0 && viscous() && volume_cavity.present() && decay[i] > 0 && kappa[i] == 0;
    if (lambda[i] == 0 && !spin_up) fail(formatted("lambda != 0 (row %zu)", i + 1));
    if (!spin_up && std::abs(kappa[i] * lambda[i] - 2) > 1e-9) fail(formatted("kappa = 2/lambda (row %zu: kappa %.9g, lambda %.9g)", i + 1, kappa[i], lambda[i]));
    if (!(N2[i] > 0)) fail(formatted("N2 > 0 (row %zu: %.9g)", i + 1, N2[i]));
    if (!viscous() && !partially_filled() && std::abs(lambda[i]) > 2 * (1 + 1e-9))
      fail(formatted("|lambda| <= 2 for an ideal fluid (row %zu: %.9g)", i + 1, lambda[i]));
    if (!viscous() && a[i] < 0) fail(formatted("a >= 0, the normalisation a = sqrt(E N2/2) (row %zu: %.9g)", i + 1, a[i]));
    const std::complex<double> a_c(a[i], viscous() ? a_imag[i] : 0.0), E_c(E[i], viscous() ? E_imag[i] : 0.0);
    if (std::abs(E_c - 2.0 * a_c * a_c / N2[i]) > 1e-8 * std::abs(E_c) + tiny)
      fail(formatted("E = 2 a^2/N2 (row %zu: E %.9g, a %.9g, N2 %.9g)", i + 1, E[i], a[i], N2[i]));
  }
}

double ModeTable::sum_rule_about(double c) const {
  if (!free_surface.present()) return sum_rule;
  const FreeSurface& f = free_surface;
  return A_f + volume * c * c + f.K(c) - (J_zh + 2 * c * f.J1 + c * c * f.J2);
}

std::string cavity_difference(const ModeTable& a, const ModeTable& b) {
  if (a.shape != b.shape) return "a " + a.shape + " and a " + b.shape;
  if (a.dimensions.size() != b.dimensions.size()) return "their dimensions differ (names)";
  for (const auto& [k, v] : a.dimensions) {
    const auto it = b.dimensions.find(k);
    if (it == b.dimensions.end() || std::abs(it->second - v) > 1e-12 * std::abs(v)) return "their dimension " + k + " differs";
  }
  if (a.free_surface.present() != b.free_surface.present() ||
      std::abs(a.free_surface.fill - b.free_surface.fill) > 1e-12)
    return "their fills differ (" + formatted("%g", a.free_surface.fill) + " and " + formatted("%g", b.free_surface.fill) + ")";
  if (!a.geometry_text.empty() && !b.geometry_text.empty() && a.geometry_text != b.geometry_text)
    return "different section files (their stored texts differ; cavity-modes info FILE --geometry prints each)";
  return {};
}

void ModeTable::sort_by_energy() {
  std::vector<std::size_t> idx(E.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) { return E[i] > E[j]; });
  auto permute = [&](auto& v) {
    if (v.empty()) return;
    auto old = v;
    for (std::size_t k = 0; k < idx.size(); ++k) v[k] = old[idx[k]];
  };
  permute(kappa); permute(lambda); permute(E); permute(a); permute(N2); permute(residual);
  permute(spread); permute(members); permute(dlambda); permute(dE); permute(converged);
  permute(decay); permute(E_imag); permute(a_imag);
  permute(galerkin.coupling_re); permute(galerkin.coupling_im);
  permute(free_surface.t);
  permute(free_surface.t_imag);
  const auto permute_blocks = [&](std::vector<double>& v, std::size_t w) {
    if (v.size() != w * idx.size()) return;
    const auto old = v;
    for (std::size_t k = 0; k < idx.size(); ++k)
      std::copy(old.begin() + w * idx[k], old.begin() + w * idx[k] + w, v.begin() + w * k);
  };
  permute_blocks(volume_cavity.coupling_re, 9);
  permute_blocks(volume_cavity.coupling_im, 9);
  permute_blocks(volume_free_surface.coupling_re, 25);
  permute_blocks(volume_free_surface.coupling_im, 25);
  const std::size_t n = idx.size();
  for (auto* m : {&galerkin.gram_re, &galerkin.gram_im, &galerkin.viscous_re, &galerkin.viscous_im}) {
    if (m->size() != n * n) continue;
    const auto old = *m;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) (*m)[i * n + j] = old[idx[i] * n + idx[j]];
  }
}

std::filesystem::path xdmf_companion(const std::filesystem::path& table_path) {
  return std::filesystem::path(table_path).replace_extension(".xdmf");
}

void write_mode_table(const ModeTable& t, const std::filesystem::path& path, const ModeFields* fields) {
  t.validate();
  if (fields) check_companion_name(path);
  quiet_hdf5();
  const std::filesystem::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
  const std::filesystem::path xdmf = xdmf_companion(path), xdmf_tmp = xdmf.string() + ".tmp" + std::to_string(::getpid());
  try {
    {
      // HDF5 1.8's file format and later: superblock version 2 and version 2 object headers, whose metadata carry
      // checksums, so that a damaged table is refused on opening rather than read (the default, the oldest format,
      // has none).
      Hid fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      if (!fapl.ok() || H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST) < 0)
        throw std::runtime_error("cannot set HDF5's file format bounds");
      Hid file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
      if (!file.ok()) throw std::runtime_error("cannot create " + path.string());
      hid_t root = file.get();
      write_root_attributes(root, t);
      write_modes_group(root, t);
      write_optional_groups(root, t);
      if (fields) write_fields_group(root, *fields);
    }
    // The companion names the table by its final name, relative to their common folder.
    if (fields) write_text_file(xdmf_tmp, fields_xdmf(*fields, path.filename().string()));
    std::filesystem::rename(tmp, path);
    if (!fields) {
      remove_stale_companion(xdmf);
      return;
    }
    try {
      std::filesystem::rename(xdmf_tmp, xdmf);
    } catch (...) {
      std::error_code ec;
      std::filesystem::remove(path, ec);  // a table whose companion could not be written is not left behind
      throw;
    }
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    std::filesystem::remove(xdmf_tmp, ec);
    throw;
  }
}

ModeTable read_mode_table(const std::filesystem::path& path) {
  quiet_hdf5();
  try {
    if (!std::filesystem::exists(path)) throw std::runtime_error("no such file");
    if (H5Fis_hdf5(path.c_str()) <= 0) throw std::runtime_error("not an HDF5 file");
    Hid file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file.ok()) throw std::runtime_error("cannot open");
    hid_t root = file.get();
    H5F_info2_t info;
    const bool checksummed = H5Fget_info2(root, &info) >= 0 && info.super.version >= 2;
    if (!has_attr(root, "format") || get_string(root, "format") != kModeTableFormat)
      throw std::runtime_error("not a mode table (root attribute format != \"cavity-mode-table\")");
    ModeTable t;
    read_root_attributes(root, t);
    read_modes_group(root, t);
    read_optional_groups(root, t);
    t.validate();
    t.checksummed = checksummed;
    return t;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace rc
