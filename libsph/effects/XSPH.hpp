// XSPH advection velocity near the free surface (Monaghan 1992; docs/method.md 10):
//   du_i = epsilon sum_{fluid j in S_i} V (u_j - u_i) W_ij,   i fluid in free, splash or vicinity,
// with u the corrected velocity u^{n+1}. Added to the advection velocity only
// (r' = r + dt (u + du)); the stored velocity is unchanged. Interior particles
// and walls get nothing; wall neighbours are not in the sum.
// Reads (system/sphSchemes, xsph): epsilon (declared in XSPH.cpp).
#pragma once
#include "effects/Effect.hpp"

namespace shizuku {

template <int D>
class XSPH final : public AdvectionVelocityEffect<D> {
 public:
  explicit XSPH(double epsilon) : AdvectionVelocityEffect<D>("xsph"), epsilon_(epsilon) {}
  std::string describe() const override { return cat("epsilon = ", epsilon_, ", on free-surface and vicinity particles"); }
  void addAdvectionVelocity(const FlowState<D>& s, const std::vector<Vec<D>>& uNew,
                            std::vector<Vec<D>>& du) override;

 private:
  double epsilon_;
};

}  // namespace shizuku
