// writeFormat ascii (docs/design.md 1.3): one plain-text file per particle field in
// the time directory, named after the field ("position", "U", "p", "rhoN",
// "type", "surface", "id", and "normal", "shift" when present). Each starts
// with '#' lines (field, unit, time, particle count, columns), then one line
// per particle in particle order: the value, or the D components separated by
// spaces; doubles in the shortest text that reads back exactly. Readable by
// numpy.loadtxt, gnuplot, awk. Dictionary keys read: none (the solver passes
// writeFormat).
#pragma once
#include "io/TimeDirectory.hpp"
#include <string>

namespace shizuku {

// Writes <dir>/<field> for each field, each file fsynced. Throws
// std::runtime_error naming the file on failure.
template <int D> void writeAsciiFields(const std::string& dir, const ParticleSet<D>& p, double time);

}  // namespace shizuku
