// A finite circular cylinder (3D) as a SolidShape (SolidShape.hpp): particlesDict
// `shape cylinder; point1 (..); point2 (..); radius R;`, the axis from point1 to point2,
// flat end caps through them. With t = (x - point1).a along the unit axis a (length L) and
// r the distance from the axis, phi is the exact signed distance:
//   inside (0 < t < L, r < R): -min(R - r, t, L - t);
//   outside: the length of (max(r - R, 0), max(-t, t - L, 0)).
// Reads no keys (ShapeRegion.cpp reads point1, point2, radius).
#pragma once
#include "particles/SolidShape.hpp"
#include <algorithm>

namespace shizuku {

class CylinderShape final : public SolidShape<3> {
 public:
  CylinderShape(const Vec<3>& point1, const Vec<3>& point2, double radius)
      : p1_(point1), length_((point2 - point1).norm()), radius_(radius) {
    axis_ = (point2 - point1) / length_;
    // Each cap is a disc of radius R normal to a: it reaches R sqrt(1 - a_k^2) along k.
    for (int k = 0; k < 3; ++k) {
      const double e = radius * std::sqrt(std::max(0.0, 1 - axis_[k] * axis_[k]));
      lower_[k] = std::min(point1[k], point2[k]) - e;
      upper_[k] = std::max(point1[k], point2[k]) + e;
    }
  }
  double phi(const Vec<3>& x) const override {
    const Vec<3> v = x - p1_;
    const double t = v.dot(axis_);
    const double r = (v - t * axis_).norm();
    const double dr = r - radius_, dt = std::max(-t, t - length_);
    if (dr <= 0 && dt <= 0) return std::max(dr, dt);
    return std::hypot(std::max(dr, 0.0), std::max(dt, 0.0));
  }
  std::string kind() const override { return "solid cylinder"; }
  double volume() const override { return M_PI * radius_ * radius_ * length_; }
  double shellVolume(double depth) const override {
    const double r = std::max(0.0, radius_ - depth), l = std::max(0.0, length_ - 2 * depth);
    return volume() - M_PI * r * r * l;
  }
  // The row (s, y, z): u = s - point1_x gives t = u a_x + c0 and
  // r^2 = u^2 (1 - a_x^2) - 2 u a_x c0 + w^2 - c0^2 (w: the row's offset from point1 in y, z).
  // The caps bound u linearly, the radius quadratically (skipped when the axis is within
  // 1e-3 rad of x: the caps and the bounding box bound the row then); both widened by margin.
  bool rowSpan(const Vec<3>& rowPoint, double margin, double& lo, double& hi) const override {
    const double wy = rowPoint[1] - p1_[1], wz = rowPoint[2] - p1_[2], ax = axis_[0];
    const double c0 = wy * axis_[1] + wz * axis_[2];
    double ulo = lower_[0] - margin - p1_[0], uhi = upper_[0] + margin - p1_[0];
    if (std::abs(ax) > 1e-12) {
      const double a = (-margin - c0) / ax, b = (length_ + margin - c0) / ax;
      ulo = std::max(ulo, std::min(a, b));
      uhi = std::min(uhi, std::max(a, b));
    } else if (c0 < -margin || c0 > length_ + margin) {
      return false;
    }
    const double A = 1 - ax * ax, R = radius_ + margin;
    if (A > 1e-6) {
      const double disc = ax * c0 * ax * c0 - A * (wy * wy + wz * wz - c0 * c0 - R * R);
      if (disc < 0) return false;
      const double s = std::sqrt(disc);
      ulo = std::max(ulo, (ax * c0 - s) / A - margin);
      uhi = std::min(uhi, (ax * c0 + s) / A + margin);
    }
    if (ulo > uhi) return false;
    lo = p1_[0] + ulo;
    hi = p1_[0] + uhi;
    return true;
  }

 private:
  Vec<3> p1_, axis_;
  double length_, radius_;
};

}  // namespace shizuku
