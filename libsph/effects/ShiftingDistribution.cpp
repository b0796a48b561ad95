// OPS (eqs. 11-13) and DPS (eq. 14) distribution shifts; formulas, signs and
// keys in ShiftingDistribution.hpp (docs/method.md 6, 7).
#include "effects/ShiftingDistribution.hpp"
#include "effects/EffectFactories.hpp"
#include "core/Parameter.hpp"
#include <cmath>

namespace shizuku {

namespace {
namespace key {
const ParameterGroup distribution("system/sphSchemes: shifting/distribution",
    "Particle-distribution shift: OPS (eqs. 11-13) or DPS (eq. 14), docs/method.md 6-7.");
const OptionParameter type = distribution.option("type", {"OPS", "DPS"}, "OPS (Lind et al.) or DPS (Morikawa)").def("OPS");
const ScalarParameter C = distribution.scalar("C", dim::none, "coefficient (OPS: <= 0.5)").def(0.2).min(0).max(10);
const ScalarParameter Rp = distribution.scalar("Rp", dim::none, "OPS anti-clumping amplitude").def(0.2).min(0);
const ScalarParameter np = distribution.scalar("np", dim::none, "OPS anti-clumping exponent").def(4).min(0);
const OptionParameter gradient = distribution.option("gradient", {"kernel", "corrected", "concentration"},
    "OPS gradient of the concentration").def("kernel");
const ScalarParameter projectionThreshold = distribution.scalar("projectionThreshold", dim::none,
    "|sum V grad W| h below which a vicinity particle is shifted like an interior one").def(0.01).min(0);
}  // namespace key
}  // namespace

template <int D>
std::unique_ptr<Effect<D>> makeShiftingDistribution(const Dictionary& d, const FlowState<D>&) {
  DistributionParameters p;
  p.type = key::type.read(d) == "OPS" ? DistributionParameters::Type::OPS : DistributionParameters::Type::DPS;
  p.C = key::C.read(d);
  if (p.type == DistributionParameters::Type::OPS) {
    if (p.C > 0.5) d.error("C", "must be <= 0.5 with type OPS (stability of the shifting diffusion, docs/method.md 6)");
    p.Rp = key::Rp.read(d);
    p.np = key::np.read(d);
    const std::string g = key::gradient.read(d);
    using G = DistributionParameters::Gradient;
    p.gradient = g == "kernel" ? G::kernel : g == "corrected" ? G::corrected : G::concentration;
  }
  p.projectionThreshold = key::projectionThreshold.read(d);
  return std::make_unique<ShiftingDistribution<D>>(p);
}

namespace {
const char* gradientName(DistributionParameters::Gradient g) {
  switch (g) {
    case DistributionParameters::Gradient::kernel: return "kernel";
    case DistributionParameters::Gradient::corrected: return "corrected (SPH2 weights, non-difference)";
    case DistributionParameters::Gradient::concentration: return "concentration (SPH2 difference form)";
  }
  return "?";
}

// The frame of a free or splash particle beside a wall that rises above the water (docs/method.md
// 6, "beside a dry wall"). Where the surface fit (8.2) holds for i and some wall neighbour j lies
// beyond the surface, d0/2 outside i along the fitted normal ((r_j - r_i) . n_fit > d0/2, the
// surface of eq. 6b), the detector's normal is tilted away from that wall (its kernel sum reads
// the dry wall as fluid where the other side is air) and the dry wall pushes i along the surface:
// i then projects with n_fit and leaves out the wall particles beyond the surface. Returns false
// (frame unchanged) otherwise.
template <int D>
bool besideDryWall(const FlowState<D>& s, std::size_t i, Vec<D>& n, double& beyond) {
  if (s.fitDistance.size() != s.size() || !std::isfinite(s.fitDistance[i])) return false;
  const Vec<D>& nFit = s.fitNormal[i];
  const double surface = 0.5 * s.d0;
  const auto& nl = s.neighbours;
  for (Index k = nl.begin(i); k < nl.end(i); ++k)
    if (!s.isFluid(nl.j[k]) && -nl.rij(i, k).dot(nFit) > surface) {
      n = nFit;
      beyond = surface;
      return true;
    }
  return false;
}

// x^whole for a whole exponent of at least 1, by repeated multiplication (((x x) x) x for the
// default np = 4), for one value or two (DoublePair) alike.
template <class T>
inline T wholePower(T x, int whole) {
  T r = x;
  for (int k = 1; k < whole; ++k) r *= x;
  return r;
}
// x^p: wholePower when p is a small whole number, else std::pow.
inline double power(double x, double p, int whole) {
  if (whole < 0) return std::pow(x, p);
  return whole == 0 ? 1.0 : wholePower(x, whole);
}
}  // namespace

template <int D>
std::string ShiftingDistribution<D>::describe() const {
  if (this->par_.type == DistributionParameters::Type::DPS)
    return cat("type DPS (eq. 14), C = ", this->par_.C, " (shift length C h), neighbours within 1.1 sqrt(D) d0",
               ", projected where |sum V grad W| h >= ", this->par_.projectionThreshold);
  return cat("type OPS (eqs. 11-13), C = ", this->par_.C, " (times h^2), Rp = ", this->par_.Rp, ", np = ", this->par_.np,
             ", gradient ", gradientName(this->par_.gradient), ", projected where |sum V grad W| h >= ",
             this->par_.projectionThreshold);
}

template <int D>
void ShiftingDistribution<D>::addShift(const FlowState<D>& s, std::vector<Vec<D>>& dr) {
  using G = DistributionParameters::Gradient;
  const auto& nl = s.neighbours;
  const auto& nrm = s.particles.normal;
  const auto& rho = s.particles.density;
  const double V = s.V(), h = s.h, invRho0 = 1.0 / s.rho0;
  const bool ops = this->par_.type == DistributionParameters::Type::OPS;
  const double invW0 = 1.0 / s.kernel.w(s.d0);
  const double coeff = ops ? -this->par_.C * h * h * V : this->par_.C * h * V;
  const double rStar = 1.1 * std::sqrt(double(D)) * s.d0;
  const bool haveWeights = !s.weights.gradW.empty() && !s.weights.order.empty();
  const bool haveGradC = s.gradC.size() == s.size();
  const int wholeNp = (this->par_.np == std::floor(this->par_.np) && this->par_.np >= 0 && this->par_.np <= 16) ? int(this->par_.np) : -1;
  const long n = long(s.size());
  long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (long i = 0; i < n; ++i) {
    if (!s.isFluid(i)) continue;
    const SurfaceClass cls = s.surfaceClass(i);
    // Projected: free and splash particles, and vicinity particles whose kernel-gradient
    // sum |sum_j V grad W_ij| h (the detector's gradC) reaches projectionThreshold, i.e.
    // whose support reaches past the surface. Deeper vicinity particles have a full
    // neighbourhood and an ill-defined normal: they shift like interior ones.
    const bool deepVicinity =
        cls == SurfaceClass::vicinity && haveGradC && s.gradC[i].norm() * h < this->par_.projectionThreshold;
    const bool project = cls != SurfaceClass::interior && !deepVicinity;
    Vec<D> ni = nrm.size() == s.size() ? nrm[i] : Vec<D>::Zero();
    double beyond = INFINITY;  // wall particles farther than this along ni are left out
    const bool dry = project && cls != SurfaceClass::vicinity && besideDryWall(s, std::size_t(i), ni, beyond);
    if (project && ni.squaredNorm() < 0.25) continue;
    // Particles without SPH(2) weights fall back to the kernel gradient.
    const G grad = (haveWeights && s.weights.order[i] != 255) ? this->par_.gradient : G::kernel;
    const double Ci = rho[i] * invRho0;
    Vec<D> sum = Vec<D>::Zero();
    Index k = nl.begin(i);
    const Index e = nl.end(i);
    // OPS with the kernel gradient (the default) two pairs at a time: one packed square
    // root, kernel evaluation, division and clumping power for both, then each pair's term
    // added in order (the scalar loop's bits).
    if (ops && grad == G::kernel && wholeNp >= 1)
      for (; k + 1 < e; k += 2) {
        Vec<D> rij[2];
        const DoublePair r = nl.r2(std::size_t(i), std::size_t(k), rij);
        DoublePair wv, dw;
        s.kernel.eval(r, wv, dw);
        const DoublePair factor = 1.0 + this->par_.Rp * wholePower(wv * invW0, wholeNp);
        const DoublePair dwOverR = dw / r;
        for (int lane = 0; lane < 2; ++lane) {
          if (!(r[lane] > 0) || (dry && !s.isFluid(nl.j[k + lane]) && -rij[lane].dot(ni) > beyond)) continue;
          const Vec<D> gradW = dwOverR[lane] * rij[lane];
          sum += factor[lane] * gradW;
        }
      }
    for (; k < e; ++k) {
      const Vec<D> rij = nl.rij(std::size_t(i), k);
      const double r = rij.norm();
      if (!(r > 0) || (dry && !s.isFluid(nl.j[k]) && -rij.dot(ni) > beyond)) continue;
      if (ops) {
        double wv, dw;
        s.kernel.eval(r, wv, dw);
        const double clump = this->par_.Rp * power(wv * invW0, this->par_.np, wholeNp);
        const Vec<D> gradW = (dw / r) * rij;
        switch (grad) {
          case G::kernel: sum += (1.0 + clump) * gradW; break;
          case G::corrected: sum += (1.0 + clump) * s.weights.gradW[k]; break;
          case G::concentration:
            sum += (rho[nl.j[k]] * invRho0 - Ci) * s.weights.gradW[k] + clump * gradW;
            break;
        }
      } else if (r < rStar) {
        sum += (s.kernel.w(r) / r) * rij;
      }
    }
    Vec<D> d = coeff * sum;
    if (project) d -= ni.dot(d) * ni;
    dr[i] += d;
    ++count;
  }
  this->actionCount_ = count;
}

SHIZUKU_EFFECT(ShiftingDistribution, makeShiftingDistribution);

}  // namespace shizuku
