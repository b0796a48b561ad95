// Checks of a restart's particles and times: see RestartChecks.hpp (docs/reliability.md).
#include "io/RestartChecks.hpp"
#include "io/TimeName.hpp"
#include "io/VtpLayout.hpp"
#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>

namespace shizuku {

namespace {

std::string particle(const std::vector<std::int64_t>& id, std::size_t i) {
  return "particle id " + std::to_string(id[i]) + " (point " + std::to_string(i) + ")";
}

bool finite(double v) { return std::isfinite(v); }
template <int D> bool finite(const Vec<D>& v) { return v.allFinite(); }
std::string text(double v) { return exactNumber(v); }
template <int D> std::string text(const Vec<D>& v) {
  std::string s = "(";
  for (int k = 0; k < D; ++k) s += (k ? " " : "") + exactNumber(v[k]);
  return s + ")";
}

// Ids: >= 0, below the limit, unique (sorted copy: a restart reads once).
void checkIds(const std::string& path, const std::vector<std::int64_t>& id, std::int64_t limit) {
  for (std::size_t i = 0; i < id.size(); ++i)
    if (id[i] < 0 || id[i] >= limit)
      corruptVtp(path, "point " + std::to_string(i) + ": id " + std::to_string(id[i]) + " is not in 0.." +
                           std::to_string(limit - 1) + " (nextId " + std::to_string(limit) + ")");
  std::vector<std::size_t> order(id.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (id[order[k]] == id[order[k - 1]])
      corruptVtp(path, "id " + std::to_string(id[order[k]]) + " is held by points " +
                           std::to_string(std::min(order[k], order[k - 1])) + " and " +
                           std::to_string(std::max(order[k], order[k - 1])));
}

void checkCount(const std::string& path, const char* what, std::optional<std::int64_t> stated, std::int64_t found) {
  if (stated && *stated != found)
    corruptVtp(path, std::string("field data '") + what + "' states " + std::to_string(*stated) + ", the file holds " +
                         std::to_string(found) + " (particles lost or added)");
}

}  // namespace

template <int D>
ParticleCounts countParticles(const ParticleSet<D>& p, std::size_t count) {
  const auto n = long(std::min(count, p.size()));
  ParticleCounts c;
  c.fluid = std::int64_t(std::count(p.type.begin(), p.type.begin() + n, std::uint8_t(ParticleType::fluid)));
  c.wall = std::int64_t(std::count(p.type.begin(), p.type.begin() + n, std::uint8_t(ParticleType::wall)));
  c.idLimit = p.nextId;
  for (long i = 0; i < n; ++i) c.idLimit = std::max(c.idLimit, p.id[std::size_t(i)] + 1);
  return c;
}

template <int D>
void checkParticleValues(const std::string& path, const ParticleSet<D>& p, const ParticleCounts& stated) {
  checkIds(path, p.id, stated.idLimit);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.type[i] > std::uint8_t(ParticleType::outlet))
      corruptVtp(path, particle(p.id, i) + ": type " + std::to_string(p.type[i]) +
                           " is none of fluid (0), wall (1), inlet (2), outlet (3)");
    if (p.surface[i] > std::uint8_t(SurfaceClass::splash))
      corruptVtp(path, particle(p.id, i) + ": surface class " + std::to_string(p.surface[i]) + " is not 0..3");
  }
  const ParticleCounts found = countParticles(p);
  checkCount(path, "fluidParticles", stated.fluid, *found.fluid);
  checkCount(path, "wallParticles", stated.wall, *found.wall);
  auto checkFinite = [&](const char* name, const auto& v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!finite(v[i])) corruptVtp(path, particle(p.id, i) + ": " + name + " is " + text(v[i]) + ", not finite");
  };
  checkFinite("position", p.position);
  p.forEachField([&](const char* name, const auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Vec<D>>) checkFinite(name, v);
  });
}

void checkTimeAgreement(const std::string& vtpPath, const VtpTime& vtp, const std::string& timePath,
                        const TimeState& time) {
  auto same = [&](const char* field, const auto& inVtp, const char* keyword, const auto& inTime) {
    if (inVtp && *inVtp != inTime)
      throw InputError("time directory disagrees with itself: '" + vtpPath + "' field data '" + field + "' is " +
                       exactNumber(double(*inVtp)) + ", but '" + timePath + "' keyword '" + keyword + "' is " +
                       exactNumber(double(inTime)));
  };
  same("time", vtp.time, "value", time.time);
  same("TimeValue", vtp.timeValue, "value", time.time);
  same("timeIndex", vtp.step, "index", time.step);
  same("deltaT", vtp.deltaT, "deltaT", time.deltaT);
  same("deltaT0", vtp.deltaT0, "deltaT0", time.deltaT0);
}

template ParticleCounts countParticles<2>(const ParticleSet<2>&, std::size_t);
template ParticleCounts countParticles<3>(const ParticleSet<3>&, std::size_t);
template void checkParticleValues<2>(const std::string&, const ParticleSet<2>&, const ParticleCounts&);
template void checkParticleValues<3>(const std::string&, const ParticleSet<3>&, const ParticleCounts&);

}  // namespace shizuku
