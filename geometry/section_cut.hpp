// Internal to rc_geometry: a user's meridian section cut at the free surface r = b of a partially filled tank
// (docs/geometry.md, "Partially filled sections"). The built-in kernel of gmsh, in which most .geo files are written,
// has no booleans, so the section's 'fluid' region is rebuilt with the OpenCASCADE kernel in a model of its own —
// straight lines and circular arcs exactly, any other curve as an interpolating spline through kSplinePoints of its
// points — and the part r >= b is kept by a boolean cut.
#pragma once

#include <string>

namespace rc::geometry::detail {

// Throws one line when the model open now draws its own free surface (a 1D physical group 'free'): a section is drawn
// whole and --fill cuts it, so that the fill is known (docs/geometry.md, "Partially filled sections").
void refuse_drawn_free_surface(const std::string& where);

// Points of a curve that is neither a line nor a circular arc, when rebuilt as an interpolating spline.
inline constexpr int kSplinePoints = 129;

// The free-surface radius b that leaves the fraction `fill` (0 < fill < 1) of the volume 2π∫∫ r dA of the section
// open in the current gmsh model at r >= b (bisection on the cut's exact area and centroid). Leaves the open model
// as it was.
double section_free_radius(double fill, const std::string& where);

// Replaces the current gmsh model (a section just opened) by a new one holding the part r >= b of its 'fluid',
// with the physical groups "fluid", "wall" and "free" (the curves on r = b). Throws one line naming why when the
// cut leaves the liquid in more than one piece or its free surface in more than one segment.
void cut_section(double b, const std::string& where);

}  // namespace rc::geometry::detail
