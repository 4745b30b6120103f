#include "separable_forms.hpp"

namespace rc::modes {

RadialForms radial_forms(const LineSpace& R) {
  RadialForms f;
  f.A = R.bilinear([](double r, double u, double du, double v, double dv) { return (du * dv + u * v / (r * r)) * r; });
  f.B = R.bilinear([](double r, double u, double, double v, double) { return u * v * r; });
  f.C = R.bilinear([](double, double u, double du, double v, double dv) { return du * v + u * dv; });
  f.g1 = R.linear([](double r, double v, double dv) { return v + r * dv; });  // (r φ)_r
  f.g2 = R.linear([](double r, double v, double) { return r * r * v; });
  return f;
}

AxialForms axial_forms(const LineSpace& Z, double centroid_z) {
  AxialForms f;
  f.A = Z.bilinear([](double, double, double du, double, double dv) { return du * dv; });
  f.B = Z.bilinear([](double, double u, double, double v, double) { return u * v; });
  f.s = Z.linear([&](double z, double v, double) { return (z - centroid_z) * v; });
  f.t = Z.linear([](double, double, double dv) { return dv; });
  return f;
}

}  // namespace rc::modes
