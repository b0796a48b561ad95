// Operators applied with precomputed pair weights (methods.md 3.2):
//   <grad f>_i = sum_j V (f_j - f_i) tilde gradW_ij,  <div u>_i = sum_j V (u_j - u_i) . tilde gradW_ij,
//   <grad u>_i = sum_j V (u_j - u_i) (x) tilde gradW_ij,  <lap f>_i = sum_j V (f_j - f_i) tilde lapW_ij.
// Rows of particles without weights (order 255) give zero. OpenMP over particles;
// outputs are resized to the particle count (no allocation once large enough).
// Reads no dictionary keys.
#include "operators/DerivativeOperator.hpp"

namespace shizuku {

template <int D>
void Ops<D>::gradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double V,
                      const std::vector<double>& f, std::vector<Vec<D>>& out) {
  const std::size_t n = nl.numParticles();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> g = Vec<D>::Zero();
    const double fi = f[i];
    for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p) g += (f[nl.j[p]] - fi) * pw.gradW[p];
    out[i] = V * g;
  }
}

template <int D>
void Ops<D>::divergence(const NeighbourList<D>& nl, const PairWeights<D>& pw, double V,
                        const std::vector<Vec<D>>& u, std::vector<double>& out) {
  const std::size_t n = nl.numParticles();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double d = 0;
    const Vec<D> ui = u[i];
    for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p) d += (u[nl.j[p]] - ui).dot(pw.gradW[p]);
    out[i] = V * d;
  }
}

template <int D>
void Ops<D>::laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double V,
                       const std::vector<double>& f, std::vector<double>& out) {
  const std::size_t n = nl.numParticles();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double l = 0;
    const double fi = f[i];
    for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p) l += (f[nl.j[p]] - fi) * pw.lapW[p];
    out[i] = V * l;
  }
}

template <int D>
void Ops<D>::laplacian(const NeighbourList<D>& nl, const PairWeights<D>& pw, double V,
                       const std::vector<Vec<D>>& u, std::vector<Vec<D>>& out) {
  const std::size_t n = nl.numParticles();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> l = Vec<D>::Zero();
    const Vec<D> ui = u[i];
    for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p) l += (u[nl.j[p]] - ui) * pw.lapW[p];
    out[i] = V * l;
  }
}

template <int D>
void Ops<D>::velocityGradient(const NeighbourList<D>& nl, const PairWeights<D>& pw, double V,
                              const std::vector<Vec<D>>& u, std::vector<Mat<D>>& out) {
  const std::size_t n = nl.numParticles();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Mat<D> g = Mat<D>::Zero();
    const Vec<D> ui = u[i];
    for (Index p = nl.offset[i]; p < nl.offset[i + 1]; ++p)
      g.noalias() += (u[nl.j[p]] - ui) * pw.gradW[p].transpose();
    out[i] = V * g;
  }
}

template struct Ops<2>;
template struct Ops<3>;

}  // namespace shizuku
