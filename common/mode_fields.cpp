#include "mode_fields.hpp"

#include "hdf5_handle.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace rc {
namespace {

hid_t create_group(hid_t loc, const std::string& name) {
  const hid_t g = H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) throw std::runtime_error("cannot create group " + name);
  return g;
}

template <class T>
void attribute(hid_t loc, const std::string& name, T value, hid_t type) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid attr(H5Acreate2(loc, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), type, &value) < 0) throw std::runtime_error("cannot write attribute " + name);
}

void text_attribute(hid_t loc, const std::string& name, const std::string& value) {
  Hid type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  Hid attr(H5Acreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::string buf = value.empty() ? std::string(1, '\0') : value;
  if (!attr.ok() || H5Awrite(attr.get(), type.get(), buf.data()) < 0)
    throw std::runtime_error("cannot write attribute " + name);
}

// A rows × columns dataset (columns = 1: one-dimensional).
template <class T>
void dataset(hid_t loc, const std::string& name, const std::vector<T>& v, std::size_t columns, hid_t type) {
  const hsize_t dims[2] = {v.size() / columns, columns};
  Hid space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose);
  Hid set(H5Dcreate2(loc, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.ok() || (!v.empty() && H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0))
    throw std::runtime_error("cannot write dataset " + name);
}

std::string mode_group(std::size_t row) { return "mode_" + std::to_string(row); }

void check_finite(const std::vector<double>& v, const std::string& what) {
  for (double x : v)
    if (!std::isfinite(x)) throw std::runtime_error("fields: " + what + " holds a non-finite value");
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// One HDF5-backed DataItem: "<file>:<dataset>", as XDMF names heavy data.
std::string data_item(const std::string& h5, const std::string& dataset, const std::string& dims, bool integer,
                      const std::string& indent) {
  return indent + "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + (integer ? "Int" : "Float") +
         "\" Precision=\"" + (integer ? "4" : "8") + "\" Format=\"HDF\">" + h5 + ":" + dataset + "</DataItem>\n";
}

// The texts of a 3-D cavity's /fields (docs/volume.md §5).
void describe_volume_fields(hid_t fields) {
  text_attribute(fields, "points", "mesh/points are (x, y, z) in the spin frame (z the spin axis), in the geometry's "
                                   "coordinates (not centroid-relative)");
  text_attribute(fields, "phase_convention",
                 "3-D modes: the velocity is Re[(V + i V_imag) exp(i lambda t)] in the frame turning with the body "
                 "(omega0 = 1), complex amplitudes of (V_x, V_y, V_z); p and p_imag those of the pressure P");
  text_attribute(fields, "normalisation",
                 "each field int |V|^2 dtau = 1; energy_density = |V_x|^2 + |V_y|^2 + |V_z|^2 per unit volume; a = "
                 "u^H c >= 0 with c_k = int (e_k x r).V (r from the centroid) and u the unit axis of the row's "
                 "coupling tensor's largest eigenvalue (a^2 is that eigenvalue when the row's modes were re-found)");
  text_attribute(fields, "cluster_field",
                 "the rotation field about u projected on the row's modes (sum over them of V_l c_l^H u / |V_l|^2), "
                 "normalised: the flow the row carries when the body turns about u");
}

void describe_meridian_fields(hid_t fields, bool damped) {
  text_attribute(fields, "points",
                 "mesh/points are (r, 0, z): the meridian half-plane phi = 0, z along the symmetry axis, in the "
                 "geometry's coordinates (not centroid-relative)");
  if (damped) {
    text_attribute(fields, "phase_convention",
                   "damped modes of a viscous table: the velocity is Re[(V_r, V_phi, V_z) exp(i phi + i lambda t)] with "
                   "complex amplitudes; V holds their real parts and V_imag their imaginary parts (no factor i "
                   "dropped), p and p_imag those of the pressure P (docs/viscous.md, Fields)");
    text_attribute(fields, "normalisation",
                   "each mode as /modes: x^T M x = 1 (unconjugated) with a = (e1 x r, V) / (i sqrt(2 pi)) of "
                   "non-negative real part; energy_density = (|V_r|^2 + |V_phi|^2 + |V_z|^2) r / (2 pi int int "
                   "(same) r dr dz), so 2 pi int int energy_density dr dz = 1");
    text_attribute(fields, "cluster_field", "one damped mode per /modes row");
  } else {
    text_attribute(fields, "phase_convention",
                   "V = (i v_r, v_phi, i v_z) exp(i m phi) with m = 1 (docs/physics.md §2); V holds the real "
                   "amplitudes (v_r, v_phi, v_z): the factor i of V_r and V_z is dropped. At phi = 0 these are also "
                   "the x, y, z components. p is the real pressure amplitude of P = p exp(i phi)");
    text_attribute(fields, "normalisation",
                   "each mode's V has N2 = 2 pi int int (v_r^2 + v_phi^2 + v_z^2) r dr dz = 1 and a = (e1 x r, V) "
                   ">= 0, as /modes; energy_density = (v_r^2 + v_phi^2 + v_z^2) r per unit dr dz, so 2 pi int int "
                   "energy_density dr dz = 1");
    text_attribute(fields, "cluster_field",
                   "sum over the cluster's eigenpairs l of (a_l / N_l^2) V_l, normalised: the part of the coupling "
                   "flow the cluster carries (a single mode for a one-member cluster)");
  }
}

}  // namespace

void ModeFields::validate() const {
  if (dimension != 2 && dimension != 3) throw std::runtime_error("fields: dimension is neither 2 nor 3");
  const std::size_t n = num_points(), npe = element_nodes();
  if (points.size() != 3 * n || n == 0) throw std::runtime_error("fields: no mesh points");
  if (cells.size() % cell_nodes() != 0 || cells.empty()) throw std::runtime_error("fields: no sub-cells");
  if (order < 1 || elements.size() % npe != 0) throw std::runtime_error("fields: elements do not match the order");
  for (const auto* ids : {&cells, &elements})
    for (int c : *ids)
      if (c < 0 || static_cast<std::size_t>(c) >= n) throw std::runtime_error("fields: node index out of range");
  check_finite(points, "mesh/points");
  for (const Mode& m : modes) {
    if (m.p.size() != n || m.V.size() != 3 * n || m.energy_density.size() != n)
      throw std::runtime_error("fields: mode " + std::to_string(m.row) + " does not match the mesh");
    check_finite(m.p, mode_group(m.row) + "/p");
    check_finite(m.V, mode_group(m.row) + "/V");
    check_finite(m.energy_density, mode_group(m.row) + "/energy_density");
    if (complex_amplitudes() && (m.p_imag.size() != n || m.V_imag.size() != 3 * n))
      throw std::runtime_error("fields: mode " + std::to_string(m.row) + " lacks its imaginary parts");
    if (!complex_amplitudes() && !(m.p_imag.empty() && m.V_imag.empty()))
      throw std::runtime_error("fields: imaginary parts on an ideal mode");
    check_finite(m.p_imag, mode_group(m.row) + "/p_imag");
    check_finite(m.V_imag, mode_group(m.row) + "/V_imag");
  }
}

void write_fields_group(hid_t file, const ModeFields& f) {
  f.validate();
  Hid fields(create_group(file, "fields"), H5Gclose);
  if (f.dimension == 3) {
    describe_volume_fields(fields.get());
  } else {
    describe_meridian_fields(fields.get(), f.damped);
  }
  Hid mesh(create_group(fields.get(), "mesh"), H5Gclose);
  dataset(mesh.get(), "points", f.points, 3, H5T_NATIVE_DOUBLE);
  dataset(mesh.get(), "cells", f.cells, f.cell_nodes(), H5T_NATIVE_INT);
  dataset(mesh.get(), "elements", f.elements, f.element_nodes(), H5T_NATIVE_INT);
  attribute(mesh.get(), "order", static_cast<long>(f.order), H5T_NATIVE_LONG);
  if (f.dimension == 3) {
    text_attribute(mesh.get(), "cells_are", "straight sub-tetrahedra (order^3 per FE tetrahedron) through all "
                                            "Lagrange nodes");
    text_attribute(mesh.get(), "elements_are", "isoparametric Lagrange tetrahedra, gmsh local node order");
  } else {
    text_attribute(mesh.get(), "cells_are", "straight sub-triangles (order^2 per FE triangle) through all Lagrange "
                                            "nodes");
    text_attribute(mesh.get(), "elements_are", "isoparametric Lagrange triangles, gmsh local node order");
  }
  for (const auto& m : f.modes) {
    Hid g(create_group(fields.get(), mode_group(m.row)), H5Gclose);
    attribute(g.get(), "modes_row", static_cast<long>(m.row), H5T_NATIVE_LONG);
    attribute(g.get(), "lambda", m.lambda, H5T_NATIVE_DOUBLE);
    attribute(g.get(), "members", static_cast<long>(m.members), H5T_NATIVE_LONG);
    attribute(g.get(), "E_members", m.E_members, H5T_NATIVE_DOUBLE);
    attribute(g.get(), "a", m.a, H5T_NATIVE_DOUBLE);
    dataset(g.get(), "p", m.p, 1, H5T_NATIVE_DOUBLE);
    dataset(g.get(), "V", m.V, 3, H5T_NATIVE_DOUBLE);
    dataset(g.get(), "energy_density", m.energy_density, 1, H5T_NATIVE_DOUBLE);
    if (f.complex_amplitudes()) {
      dataset(g.get(), "p_imag", m.p_imag, 1, H5T_NATIVE_DOUBLE);
      dataset(g.get(), "V_imag", m.V_imag, 3, H5T_NATIVE_DOUBLE);
    }
  }
}

std::string fields_xdmf(const ModeFields& f, const std::string& h5_name) {
  const std::string h5 = xml_escape(h5_name);
  const std::string n = std::to_string(f.num_points()), cells = std::to_string(f.num_cells());
  std::ostringstream x;
  const bool volume = f.dimension == 3;
  x << "<?xml version=\"1.0\" ?>\n<!-- " << kFieldsXdmfMarker
    << (volume ? ": the 3-D cavity's tetrahedra (x, y, z) and each mode's complex p, V (spin frame) and kinetic-energy "
                 "density; docs/volume.md section 5 -->\n"
               : ": the meridian half-plane (r, 0, z) and each mode's p, V (real amplitudes, V = (i v_r, v_phi, i v_z) "
                 "exp(i phi)) and kinetic-energy density; docs/modes.md \"Fields\" -->\n")
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n    <Grid Name=\"" << (volume ? "cavity" : "meridian")
    << "\" GridType=\"Uniform\">\n"
    << "      <Topology TopologyType=\"" << (volume ? "Tetrahedron" : "Triangle") << "\" NumberOfElements=\"" << cells
    << "\">\n"
    << data_item(h5, "/fields/mesh/cells", cells + (volume ? " 4" : " 3"), true, "        ") << "      </Topology>\n"
    << "      <Geometry GeometryType=\"XYZ\">\n"
    << data_item(h5, "/fields/mesh/points", n + " 3", false, "        ") << "      </Geometry>\n";
  for (const auto& m : f.modes) {
    const std::string g = "/fields/" + mode_group(m.row) + "/", name = "mode" + std::to_string(m.row) + " ";
    auto node_attribute = [&](const std::string& what, const std::string& type, const std::string& dims) {
      x << "      <Attribute Name=\"" << name << what << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n"
        << data_item(h5, g + what, dims, false, "        ") << "      </Attribute>\n";
    };
    node_attribute("p", "Scalar", n);
    node_attribute("V", "Vector", n + " 3");
    node_attribute("energy_density", "Scalar", n);
    if (f.complex_amplitudes()) {
      node_attribute("p_imag", "Scalar", n);
      node_attribute("V_imag", "Vector", n + " 3");
    }
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

void check_companion_name(const std::filesystem::path& table_path) {
  if (table_path.extension() == ".xdmf")
    throw std::runtime_error("with --fields the table's name must not end in .xdmf (its companion is FILE.xdmf)");
  if (table_path.filename().string().find(':') != std::string::npos)
    throw std::runtime_error("with --fields the table's name must not contain ':' (XDMF separates file and "
                             "dataset with it)");
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void remove_stale_companion(const std::filesystem::path& xdmf) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(xdmf, ec)) return;
  std::ifstream in(xdmf, std::ios::binary);
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.find(kFieldsXdmfMarker) != std::string::npos) std::filesystem::remove(xdmf, ec);
}

}  // namespace rc
