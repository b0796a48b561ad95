// Function object `probes` (docs/design.md 1.3): values of particle fields at fixed
// points by Shepard-normalised SPH interpolation over the fluid particles:
//   f(x) = sum_j V f_j W(|x - x_j|) / sum_j V W(|x - x_j|),   V = m / rho0,
// j over fluid particles within the support 2h of x (walls never count).
// A point whose kernel sum S(x) = sum_j V W is below `minKernelSum` (default
// 0.5) is outside the fluid and gives nan. Measured on a cubic-spline lattice
// at h = 1.2 d0 (tests/unit/test_functionObjects_values.cpp): S = 1 at an
// interior site, 0.78 on a particle of a flat face, 0.499 half a spacing
// outside the face (the nominal fluid boundary), 0.25 (2D) / 0.13 (3D) half a
// spacing diagonally beyond a corner; a corner particle has 0.61 (2D) and
// 0.49 (3D, so nan). So 0.5 cuts at the nominal free surface.
// Linear fields are reproduced exactly where the neighbourhood is symmetric.
// Search: a bounding box of the points widened by 2h skips the particles far
// from every point (then a test against each point: O(N x points), meant for
// a few points); periodic directions use the minimum image (no box skip then).
// Sums use fixed blocks of particles, so results do not depend on the thread count.
// Fields: p (Pa), rhoN (kg/m^3), U (m/s), normal (-), shift (m); vectors are written "(x y)".
// Files: one per field, named after it: time, then the value at each point (point0, point1, ...).
// Reads (controlDict functions/<name>): type probes; fields (p U); points ((0 0) (0.1 0)) [m];
//   minKernelSum 0.5; writeControl; writeInterval.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"

namespace shizuku {

template <int D>
class Probes : public SampledFunctionObject<D> {
 public:
  Probes(const std::string& name, const Dictionary& dict);

  const std::vector<std::string>& fields() const { return fields_; }
  const std::vector<Vec<D>>& points() const { return points_; }
  // Interpolate every field at every point: values[f] holds, point after point,
  // comps(f) numbers (nan outside the fluid). Buffers are reused between calls.
  const std::vector<std::vector<double>>& evaluate(const FlowState<D>& s);
  // Kernel sums S(x_k) of the last evaluate().
  const std::vector<double>& kernelSums() const { return kernelSum_; }
  int comps(std::size_t f) const { return comps_[f]; }

  static std::vector<std::string> knownFields() { return {"p", "rhoN", "U", "normal", "shift"}; }
  static std::string fieldUnit(const std::string& field);

 protected:
  std::string details() const override;
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  const double* fieldData(const FlowState<D>& s, std::size_t f) const;
  std::vector<std::string> fields_;
  std::vector<int> comps_;
  std::vector<Vec<D>> points_;
  double minKernelSum_ = 0.5;
  std::vector<PostProcessingFile> files_;
  std::vector<double> kernelSum_;
  std::vector<std::vector<double>> values_;
  std::vector<const double*> fieldPtr_;
  std::vector<double> blockSums_;  // per block: per point (1 + sum of comps) partial sums
  std::vector<double> sums_;       // the same summed over the blocks (and the ranks)
};

extern template class Probes<2>;
extern template class Probes<3>;

}  // namespace shizuku
