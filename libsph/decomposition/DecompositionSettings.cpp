// The keys of system/decomposeParDict (docs/parallel.md 3): see DomainDecomposition.hpp.
#include "core/Parameter.hpp"
#include "decomposition/DomainDecomposition.hpp"

namespace shizuku {

namespace {
namespace key {
const ParameterGroup decompose("system/decomposeParDict",
    "Distributed runs (mpirun -np N shizuku -parallel): how Zoltan divides the particles among the ranks "
    "(docs/parallel.md).");
const OptionParameter method = decompose.option("method", {"RCB", "HSFC"},
    "RCB: recursive coordinate bisection (box-shaped regions, small halos); HSFC: Hilbert space-filling curve")
    .def("RCB");
const ScalarParameter rebalanceThreshold = decompose.scalar("rebalanceThreshold", dim::none,
    "repartition when the largest rank holds more than (1 + this) x the mean particle count").def(0.1).above(0);
const IntParameter migrationInterval = decompose.integer("migrationInterval",
    "steps between moves of particles to the rank whose region holds them (between moves the pressure "
    "preconditioner can be kept)").def(10).min(1).max(1000000);
}  // namespace key
}  // namespace

DecompositionSettings DecompositionSettings::read(const Dictionary* dict) {
  DecompositionSettings s;
  s.method = key::method.read(dict);
  s.rebalanceThreshold = key::rebalanceThreshold.read(dict);
  s.migrationInterval = key::migrationInterval.read(dict);
  return s;
}

}  // namespace shizuku
