// Optional /fields of a mode table (docs/physics.md §4): the meridian mesh and, for each kept mode (cluster), its
// pressure p and velocity V at the mesh nodes, plus the XDMF companion that lets ParaView open them.
// Layout, units and the phase convention: docs/modes.md, "Fields"; a 3-D cavity's (tetrahedra, complex amplitudes):
// docs/volume.md §5.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rc {

struct ModeFields {
  // --- /fields/mesh -----------------------------------------------------------------------------
  // dimension 2: the meridian half-plane of an axisymmetric cavity; 3: a 3-D cavity's tetrahedra, whose fields are
  // complex amplitudes (p_imag and V_imag always present) in the spin frame.
  int dimension = 2;
  std::vector<double> points;   // N × 3, row-major: (r, 0, z) of every mesh node (the half-plane φ = 0); in 3-D (x, y, z)
  std::vector<int> cells;       // M × 3: straight sub-triangles through all Lagrange nodes (what XDMF shows); in 3-D
                                // M × 4 straight sub-tetrahedra
  int order = 0;                // Lagrange order of the FE triangles (tetrahedra)
  std::vector<int> elements;    // the FE triangles, (order+1)(order+2)/2 nodes each, gmsh's local order; in 3-D the
                                // tetrahedra, (order+1)(order+2)(order+3)/6 nodes each

  // --- /fields/mode_<i>, i = row of /modes --------------------------------------------------------
  struct Mode {
    std::size_t row = 0;          // the /modes row this field belongs to
    double lambda = 0;            // λ of that row
    int members = 0;              // eigenpairs the field was formed from
    double E_members = 0;         // their E summed (reproduces /modes/E when the cluster was re-found)
    double a = 0;                 // (e1 × r, V) of the stored field computed with the FE forms
    std::vector<double> p;        // N: pressure amplitude
    std::vector<double> V;        // N × 3: real amplitudes (v_r, v_φ, v_z); V = (i v_r, v_φ, i v_z) e^{iφ}
    std::vector<double> energy_density;  // N: (v_r² + v_φ² + v_z²) r, so 2π ∫∫ (it) dr dz = N² = 1
    std::vector<double> p_imag, V_imag;  // damped modes only (N, N × 3): imaginary parts
  };
  std::vector<Mode> modes;
  // Damped modes of a viscous table (docs/viscous.md, "Fields"): complex amplitudes, V and p their real parts and
  // V_imag, p_imag (in each Mode) their imaginary parts; V is then the physical (V_r, V_phi, V_z), no factor i.
  bool damped = false;

  bool complex_amplitudes() const { return damped || dimension == 3; }
  std::size_t cell_nodes() const { return dimension == 3 ? 4 : 3; }
  std::size_t element_nodes() const {
    return dimension == 3 ? (order + 1) * (order + 2) * (order + 3) / 6 : (order + 1) * (order + 2) / 2;
  }
  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_cells() const { return cells.size() / cell_nodes(); }
  // Throws std::runtime_error if array sizes disagree, an index is out of range or a value is not finite.
  void validate() const;
};

// Writes the group /fields under `file` (an open HDF5 file). Throws std::runtime_error on failure.
void write_fields_group(hid_t file, const ModeFields& fields);

// The XDMF 3 document describing /fields of the HDF5 file `h5_name` (a name relative to the XDMF file's
// folder, as ParaView resolves it): one grid of straight triangles, and p, V, energy_density of each mode
// as node attributes "mode<i> p", "mode<i> V", "mode<i> energy_density".
std::string fields_xdmf(const ModeFields& fields, const std::string& h5_name);

// A comment every XDMF file we write carries, so that a stale companion can be recognised as ours.
// (No "--" in it: XML comments must not contain two hyphens.)
inline constexpr const char* kFieldsXdmfMarker = "written by cavity-modes with the fields option";

// Throws std::runtime_error if a table at `table_path` cannot have a companion that names it: the name
// ends in .xdmf (it would be its own companion) or holds ':' (XDMF's separator of file and dataset).
void check_companion_name(const std::filesystem::path& table_path);

// Writes `text` to `path` (a temporary name; the caller renames it). Throws std::runtime_error.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// Removes `xdmf` if it exists and is one of ours (carries kFieldsXdmfMarker): after a table is rewritten
// without fields, its old companion would point at datasets that no longer exist. Never throws.
void remove_stale_companion(const std::filesystem::path& xdmf);

}  // namespace rc
