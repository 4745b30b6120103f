#include "size_fields.hpp"

#include <gmsh.h>

namespace rc::geometry {

int distance_threshold(const DistanceTo& to, double size_min, double size_max, double dist_min, double dist_max) {
  namespace field = gmsh::model::mesh::field;
  const int distance = field::add("Distance");
  if (!to.points.empty()) field::setNumbers(distance, "PointsList", to.points);
  if (!to.curves.empty()) field::setNumbers(distance, "CurvesList", to.curves);
  if (!to.surfaces.empty()) field::setNumbers(distance, "SurfacesList", to.surfaces);
  if (to.points_per_curve > 0) field::setNumber(distance, "NumPointsPerCurve", to.points_per_curve);
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", size_min);
  field::setNumber(threshold, "SizeMax", size_max);
  field::setNumber(threshold, "DistMin", dist_min);
  field::setNumber(threshold, "DistMax", dist_max);
  return threshold;
}

}  // namespace rc::geometry
