// Derivative operators behind one interface (docs/method.md section 3), chosen by
// `derivatives SPH2|corrected|standard` in system/sphSchemes.
//
// Every operator is a weighted sum of differences over the neighbour list,
// with per-pair weights computed once per step by computeWeights():
//   <grad f>_i = sum_j V (f_j - f_i) gradW_ij
//   <div u>_i  = sum_j V (u_j - u_i) . gradW_ij
//   <lap f>_i  = sum_j V (f_j - f_i) lapW_ij
// SPH2:      full-inverse (FI) 5x5 / 9x9 moment matrix (eq. 3.2), scaled by h,
//            fallback FI -> first-order corrected -> standard per particle (3.4).
// corrected: first-order kernel-gradient correction + renormalised Laplacian (3.5).
// standard:  plain kernel gradient + Morris/Brookshaw Laplacian.
#pragma once
#include "core/types.hpp"
#include "kernels/Kernel.hpp"
#include "particles/NeighbourList.hpp"
#include <memory>
#include <string>

namespace shizuku {

enum class DerivativeScheme { SPH2, corrected, standard };
DerivativeScheme derivativeSchemeFromName(const std::string& name);  // throws InputError
std::string toString(DerivativeScheme s);

// Per-pair and per-particle weights shared by every operator in a step.
template <int D>
struct PairWeights {
  std::vector<Vec<D>> gradW;       // per pair: corrected gradient weight (tilde grad W_ij)
  std::vector<double> lapW;        // per pair: Laplacian weight (tilde lap W_ij)
  std::vector<std::uint8_t> order; // per particle: 2 = FI, 1 = first order, 0 = standard, 255 = none
};

// Fallback chain of SPH2 (docs/method.md 3.4), per particle: FI if the particle has
// at least minNeighboursFI neighbours and rcond(M) > minRcondFI, else first
// order if at least minNeighboursFirstOrder neighbours and rcond(A) >
// minRcondFirstOrder, else standard. `corrected` uses the first-order test.
// A neighbour minimum of 0 means the default of the dimension (FI: 6 in 2D,
// 12 in 3D; first order: 3 / 4). rcond is the exact 1-norm value.
// A row keeps FI or first-order weights only where its largest corrected gradient weight
// is at most maxGradientAmplification times its largest kernel gradient |dW/dr|.
// A first-order row keeps the renormalised Laplacian only where its denominator
// sum_j w_ij s_ij^2 chi_ij is at least minLaplacianRenormalisation times the
// unrenormalised sum_j w_ij s_ij^2, i.e. where renormalising amplifies the kernel's
// Laplacian weights at most tenfold; else the row's Laplacian is Morris's
// (docs/method.md 3.5).
struct FallbackThresholds {
  double minRcondFI = 1e-4;
  double minRcondFirstOrder = 1e-3;
  int minNeighboursFI = 0;
  int minNeighboursFirstOrder = 0;
  double minLaplacianRenormalisation = 0.1;
  // A row's corrected gradient weights may be at most this many times the largest kernel
  // gradient of the row; a row beyond takes the next link of the chain (docs/method.md 3.4).
  double maxGradientAmplification = 10;
};

template <int D>
class DerivativeOperator {
 public:
  virtual ~DerivativeOperator() = default;
  virtual DerivativeScheme scheme() const = 0;
  // Fill `out` for every particle i with computeFor[i] != 0 (other particles get zero
  // gradient and Laplacian weights and order 255). computeFor[i] == 2 marks a free-surface row: SPH2 starts its fallback chain
  // there at first order; 3 marks a splash row (an isolated particle): standard weights,
  // because a correction matrix built from the one to three neighbours of a droplet
  // amplifies the noise of their pressures (docs/solver.md, the weights stage).
  // V = particle volume (uniform). Parallel over particles.
  virtual void computeWeights(const Kernel<D>& kernel, double V, const NeighbourList<D>& nl,
                              const std::vector<std::uint8_t>& computeFor, PairWeights<D>& out) const = 0;
  static std::unique_ptr<DerivativeOperator> create(DerivativeScheme s);
  static std::unique_ptr<DerivativeOperator> create(DerivativeScheme s, const FallbackThresholds& t);
  const FallbackThresholds& thresholds() const { return thresholds_; }

 protected:
  FallbackThresholds thresholds_;
};

}  // namespace shizuku
