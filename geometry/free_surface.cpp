#include "free_surface.hpp"

#include "shapes.hpp"

#include <cmath>
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
  throw std::runtime_error("--fill on a section is not built yet: a partially filled section is so far one of the "
                           "built-in shapes (docs/modes.md, \"Partially filled tanks\")");
}

ShapeSpec partially_filled(ShapeSpec shape, double fill) {
  shape.dims["free_radius"] = free_surface_radius(shape, fill);
  return shape;
}

}  // namespace rc::geometry
