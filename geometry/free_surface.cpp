#include "free_surface.hpp"

#include "gmsh_session.hpp"
#include "section_cut.hpp"
#include "shapes.hpp"

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rc::geometry {

namespace {

// The root c in (0, 1) of 1 − 3c² + 2c³ = fill (decreasing in c: its derivative is −6c(1 − c)).
double cone_ratio(double fill) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double c = 0.5 * (lo + hi);
    (1 - 3 * c * c + 2 * c * c * c > fill ? lo : hi) = c;
  }
  return 0.5 * (lo + hi);
}

// A section's b: its file opened in gmsh and cut at trial radii until the liquid's volume is `fill` of the whole.
double section_radius(const ShapeSpec& shape, double fill) {
  const std::string where = "section '" + shape.file.string() + "'";
  if (shape.file.extension() != ".geo")
    throw std::runtime_error(where + ": --fill cuts a section's geometry, which only a .geo file holds");
  if (std::filesystem::is_directory(shape.file) || !std::ifstream(shape.file))
    throw std::runtime_error(where + ": cannot read the file");
  return detail::with_gmsh(where, [&](detail::GmshSession& session) {
    gmsh::open(shape.file.string());
    session.throw_if_error(where);
    return detail::section_free_radius(fill, where);
  });
}

}  // namespace

double free_surface_radius(const ShapeSpec& shape, double fill) {
  detail::validate_shape(shape);
  if (!(fill > 0 && fill < 1)) throw std::runtime_error("the fill must be in (0, 1) for a free surface");
  if (shape.kind == "sphere" || shape.kind == "spheroid") {
    const double a = shape.dims.at(shape.kind == "sphere" ? "radius" : "a");
    return a * std::sqrt(1 - std::pow(fill, 2.0 / 3.0));
  }
  if (shape.kind == "cylinder") {
    const double a = shape.dims.at("radius");
    const double rod = shape.dims.count("inner_radius") ? shape.dims.at("inner_radius") : 0.0;
    return std::sqrt(a * a - fill * (a * a - rod * rod));
  }
  if (shape.kind == "cone") return shape.dims.at("radius") * cone_ratio(fill);
  return section_radius(shape, fill);
}

ShapeSpec partially_filled(ShapeSpec shape, double fill) {
  shape.dims["free_radius"] = free_surface_radius(shape, fill);
  return shape;
}

}  // namespace rc::geometry
