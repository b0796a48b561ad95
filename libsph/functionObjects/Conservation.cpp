// Function object `conservation`: see Conservation.hpp (docs/design.md 1.3).
#include "functionObjects/Conservation.hpp"
#include "parallel/Communicator.hpp"

namespace shizuku {

namespace {
template <int D>
struct Sums {
  double volume = 0, fluidVolume = 0, kinetic = 0, count = 0;
  Vec<D> momentum = Vec<D>::Zero();
  Vec<3> angular = Vec<3>::Zero();
  Sums& operator+=(const Sums& o) {
    volume += o.volume; fluidVolume += o.fluidVolume; kinetic += o.kinetic; count += o.count;
    momentum += o.momentum; angular += o.angular;
    return *this;
  }
};

template <int D> Vec<3> lift(const Vec<D>& v) {
  Vec<3> r = Vec<3>::Zero();
  r.template head<D>() = v;
  return r;
}
}  // namespace

template <int D>
Conservation<D>::Conservation(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "conservation", dict) {}

template <int D>
ConservationValues<D> Conservation<D>::compute(const FlowState<D>& s) {
  const auto& p = s.particles;
  const double m = p.mass;
  thread_local std::vector<Sums<D>> partial;
  Sums<D> t = blockReduce(s.numOwned(), partial, [&](Sums<D>& a, std::size_t i) {
    if (!p.isFluid(i)) return;
    const Vec<D>& u = p.velocity[i];
    a.count += 1;
    a.volume += m / p.density[i];
    // A truncated kernel sum is no compression: only interior particles count theirs.
    a.fluidVolume += m / (p.surfaceClass(i) == SurfaceClass::interior ? p.density[i] : s.rho0);
    a.kinetic += 0.5 * m * u.squaredNorm();
    a.momentum += m * u;
    a.angular += m * lift<D>(p.position[i]).cross(lift<D>(u));
  });
  // Every rank's own particles (docs/parallel.md 5); the removal counts likewise.
  const auto& world = Communicator::world();
  FluidBalance balance = s.balance;
  if (world.isParallel()) {
    std::vector<double> sums = {t.volume, t.fluidVolume, t.kinetic, t.count, balance.removedMass,
                                double(balance.released), double(balance.captured)};
    for (int a = 0; a < D; ++a) sums.push_back(t.momentum[a]);
    for (int a = 0; a < 3; ++a) sums.push_back(t.angular[a]);
    world.sumInPlace(sums);
    t.volume = sums[0]; t.fluidVolume = sums[1]; t.kinetic = sums[2]; t.count = sums[3];
    balance.removedMass = sums[4]; balance.released = long(sums[5]); balance.captured = long(sums[6]);
    for (int a = 0; a < D; ++a) t.momentum[a] = sums[7 + a];
    for (int a = 0; a < 3; ++a) t.angular[a] = sums[7 + D + a];
  }
  ConservationValues<D> v;
  v.volume = t.volume;
  v.fluidVolume = t.fluidVolume;
  v.nominalVolume = t.count * m / s.rho0;
  v.fluidMass = t.count * m;
  v.removedMass = balance.removedMass;
  v.releasedMass = double(balance.released) * m;
  v.capturedMass = double(balance.captured) * m;
  v.kineticEnergy = t.kinetic;
  v.momentum = t.momentum;
  if constexpr (D == 2) v.angularMomentum[0] = t.angular[2];
  else v.angularMomentum = t.angular;
  return v;
}

template <int D>
void Conservation<D>::open(const FlowState<D>& s, const RunInfo& info) {
  openBoundaries_ = s.hasOpenBoundaries;
  this->file_.emplace(this->makeFile(info, "conservation.dat"));
  this->file_->comment(cat("conservation of the fluid particles (walls excluded), ", D, "D",
                     D == 2 ? ", per unit depth" : "", "\n",
                     "volume = sum m/<rho>_i (eq. 18); nominalVolume = N_fluid m/rho0; "
                     "fluidVolume = sum m/<rho>_i over interior particles + m/rho0 over the others;\n"
                     "kineticEnergy = sum m|u|^2/2;\n",
                     "momentum = sum m u; angularMomentum = sum m r x u about the origin",
                     D == 2 ? " (z component)" : "", ";\n",
                     "fluidMass = N_fluid m; removedMass: fluid removed through the domain's bounds since the start",
                     openBoundaries_ ? ";\nreleasedMass, capturedMass: fluid inlets released and outlets captured since "
                                       "the start" : ""));
  std::vector<std::string> names = {"time", "volume", "nominalVolume", "kineticEnergy", "momentum",
                                    "angularMomentum", "fluidMass", "removedMass", "fluidVolume"};
  std::vector<std::string> unit = {"s", units::volume(D), units::volume(D), units::energy(D), units::momentum(D),
                                   units::angularMomentum(D), units::mass(D), units::mass(D), units::volume(D)};
  if (openBoundaries_) {
    names.insert(names.end(), {"releasedMass", "capturedMass"});
    unit.insert(unit.end(), {units::mass(D), units::mass(D)});
  }
  this->file_->columns(names, unit);
}

template <int D>
void Conservation<D>::sample(const FlowState<D>& s, const RunInfo&) {
  const auto v = compute(s);
  using F = PostProcessingFile;
  std::string row = F::number(s.time) + " " + F::number(v.volume) + " " + F::number(v.nominalVolume) + " " +
                    F::number(v.kineticEnergy) + " " + F::vector<D>(v.momentum) + " ";
  if constexpr (D == 2) row += F::number(v.angularMomentum[0]);
  else row += F::vector<3>(v.angularMomentum);
  row += " " + F::number(v.fluidMass) + " " + F::number(v.removedMass) + " " + F::number(v.fluidVolume);
  if (openBoundaries_) row += " " + F::number(v.releasedMass) + " " + F::number(v.capturedMass);
  this->file_->row(row);
}

template class Conservation<2>;
template class Conservation<3>;

}  // namespace shizuku
