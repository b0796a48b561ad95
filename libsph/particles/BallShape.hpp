// A disc (2D) or a ball (3D) as a SolidShape (SolidShape.hpp): a wall region
// `shape circle|sphere` (a solid body; its layers lie inside, within `layers` d0 of the
// surface). phi(x) = |x - centre| - radius, exact everywhere.
// Reads no keys (ShapeRegion.cpp reads centre and radius).
#pragma once
#include "particles/SolidShape.hpp"
#include <algorithm>

namespace shizuku {

template <int D>
class BallShape final : public SolidShape<D> {
 public:
  BallShape(const Vec<D>& centre, double radius) : centre_(centre), radius_(radius) {
    this->lower_ = centre.array() - radius;
    this->upper_ = centre.array() + radius;
  }
  double phi(const Vec<D>& x) const override { return (x - centre_).norm() - radius_; }
  std::string kind() const override { return D == 2 ? "solid disc" : "solid ball"; }
  double volume() const override { return measure(radius_); }
  double shellVolume(double depth) const override {
    return measure(radius_) - measure(std::max(0.0, radius_ - depth));
  }
  // The chord of the row: x = cx +- sqrt(R^2 - d^2), d the row's distance from the centre.
  bool rowSpan(const Vec<D>& rowPoint, double margin, double& lo, double& hi) const override {
    double d2 = 0;
    for (int k = 1; k < D; ++k) d2 += (rowPoint[k] - centre_[k]) * (rowPoint[k] - centre_[k]);
    const double r = radius_ + margin;
    if (d2 >= r * r) return false;
    const double h = std::sqrt(r * r - d2);
    lo = centre_[0] - h;
    hi = centre_[0] + h;
    return true;
  }
  const Vec<D>& centre() const { return centre_; }
  double radius() const { return radius_; }

 private:
  static double measure(double r) { return D == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r; }
  Vec<D> centre_;
  double radius_;
};

}  // namespace shizuku
