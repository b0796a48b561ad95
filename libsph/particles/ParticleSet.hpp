// The particle arrays, structure of arrays: one contiguous std::vector per
// field. Optional fields (shift, normal, ...) stay empty unless an active
// effect allocates them, so an absent effect costs no memory. Every field is
// visited by forEachField(), which the writer, the reader and the cell
// reordering all use, so a new field is added in one place.
#pragma once
#include "core/types.hpp"
#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace shizuku {

template <int D>
struct ParticleSet {
  // --- always present -----------------------------------------------------
  std::vector<Vec<D>> position;     // m
  std::vector<Vec<D>> velocity;     // m/s (wall particles: wall velocity)
  std::vector<double> pressure;     // Pa
  std::vector<double> density;      // summation (number) density <rho>_i, kg/m^D (eq. 18)
  std::vector<std::uint8_t> type;   // ParticleType
  std::vector<std::uint8_t> surface;// SurfaceClass
  std::vector<std::int64_t> id;     // original index, stable under reordering
  // --- optional (empty when no active effect needs them) -------------------
  std::vector<Vec<D>> normal;       // outward unit normal near the free surface
  std::vector<Vec<D>> shift;        // last particle shift delta r (m)
  std::vector<Vec<D>> restPosition; // wall particles of a case with moving walls: where particlesDict built them (m)
  std::vector<std::uint8_t> motion; // moving wall particles: their motion's index + 1 (0: fixed)
  std::vector<Vec<D>> wallNormal;   // wall particles: their wall surface's unit normal, out of the wall (WallNormals.hpp)
  std::vector<Vec<D>> restNormal;   // wall particles of a case with moving walls: wallNormal at the rest position

  double mass = 0;        // particle mass (kg, or kg/m in 2D), calibrated on the initial lattice
  double rho0 = 1000;     // reference density
  double spacing = 0;     // d0 (m)
  std::int64_t nextId = 0;  // the id the next new particle takes (inlets); every id is below it

  std::size_t size() const { return position.size(); }
  double volume() const { return mass / rho0; }
  bool isFluid(std::size_t i) const { return type[i] == std::uint8_t(ParticleType::fluid); }
  bool isWall(std::size_t i) const { return type[i] == std::uint8_t(ParticleType::wall); }
  bool isInlet(std::size_t i) const { return type[i] == std::uint8_t(ParticleType::inlet); }
  bool isOutlet(std::size_t i) const { return type[i] == std::uint8_t(ParticleType::outlet); }
  SurfaceClass surfaceClass(std::size_t i) const { return SurfaceClass(surface[i]); }

  // Visit every field as (name, vector&). Names are the ones written to VTK.
  template <class F> void forEachField(F&& f) {
    f("U", velocity); f("p", pressure); f("rhoN", density); f("type", type);
    f("surface", surface); f("id", id); f("normal", normal); f("shift", shift);
    f("restPosition", restPosition); f("motion", motion); f("wallNormal", wallNormal);
    f("restNormal", restNormal);
  }
  template <class F> void forEachField(F&& f) const {
    const_cast<ParticleSet*>(this)->forEachField(
        [&](const char* n, auto& v) { f(n, static_cast<const std::decay_t<decltype(v)>&>(v)); });
  }

  // Visit every field of this set with the same field of o, as (vector&, const vector&).
  template <class F> void forEachFieldWith(const ParticleSet& o, F&& f) {
    int k = 0;
    forEachField([&](const char*, auto& v) {
      int j = 0;
      o.forEachField([&](const char*, const auto& w) {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::decay_t<decltype(w)>>)
          if (j == k) f(v, w);
        ++j;
      });
      ++k;
    });
  }

  // Resize all present fields (and the mandatory ones) to n.
  void resize(std::size_t n) {
    position.resize(n);
    forEachField([&](const char* name, auto& v) {
      if (!v.empty() || isMandatory(name)) v.resize(n);
    });
  }
  // Remove the particles with remove[i] != 0, keeping the order of the others (ids
  // unchanged): every present field is compacted in place, capacity kept. Returns the
  // new size.
  std::size_t removeMarked(const std::vector<std::uint8_t>& remove) {
    auto compact = [&](auto& v) {
      if (v.size() != remove.size()) return;
      std::size_t k = 0;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (!remove[i]) v[k++] = v[i];
      v.resize(k);
    };
    compact(position);
    forEachField([&](const char*, auto& v) { compact(v); });
    return position.size();
  }
  // Append a copy of particle i (every present field); returns the new particle's index.
  std::size_t addCopy(std::size_t i) {
    position.push_back(position[i]);
    forEachField([&](const char*, auto& v) {
      if (v.size() + 1 == position.size()) v.push_back(v[i]);
    });
    return position.size() - 1;
  }
  // Reorder: particle k becomes the old particle order[k] (every present field; a copy
  // of each field is made, so not for the time loop).
  template <class I> void permute(const std::vector<I>& order) {
    auto apply = [&](auto& v) {
      if (v.size() != order.size()) return;
      const auto copy = v;
      for (std::size_t k = 0; k < order.size(); ++k) v[k] = copy[std::size_t(order[k])];
    };
    apply(position);
    forEachField([&](const char*, auto& v) { apply(v); });
  }
  // Sort the particles by id (a copy of each field, as permute).
  void sortById() {
    std::vector<std::size_t> order(size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
    permute(order);
  }
  // Keep particles first .. last - 1 alone.
  void keepRange(std::size_t first, std::size_t last) {
    std::vector<std::uint8_t> outside(size(), 0);
    for (std::size_t i = 0; i < size(); ++i) outside[i] = i < first || i >= last;
    removeMarked(outside);
  }
  // Append every particle of o, keeping its fields' order. False (nothing appended) when
  // both sets hold particles and a field is present in one and absent in the other.
  bool append(const ParticleSet& o) {
    const std::size_t n = size(), m = o.size();
    bool agree = true;
    forEachFieldWith(o, [&](auto& v, const auto& w) { agree = agree && (n == 0 || m == 0 || v.empty() == w.empty()); });
    if (!agree) return false;
    position.insert(position.end(), o.position.begin(), o.position.end());
    forEachFieldWith(o, [&](auto& v, const auto& w) { v.insert(v.end(), w.begin(), w.end()); });
    return true;
  }
  static bool isMandatory(const std::string& name) {
    return name == "U" || name == "p" || name == "rhoN" || name == "type" || name == "surface" || name == "id";
  }
  std::size_t countFluid() const {
    std::size_t n = 0;
    for (auto t : type) n += (t == std::uint8_t(ParticleType::fluid));
    return n;
  }
};

}  // namespace shizuku
