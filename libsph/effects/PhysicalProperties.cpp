// The declared keys of constant/physicalProperties and constant/g: see PhysicalProperties.hpp.
#include "effects/PhysicalProperties.hpp"
#include "core/Parameter.hpp"

namespace shizuku {

namespace {
namespace key {
const ParameterGroup properties("constant/physicalProperties", "The fluid's density, viscosity and (optional) sound speed.");
// A density below 1e-3 kg/m^3 (far below any liquid, or a gas at ordinary pressure) makes
// every pressure (p ~ rho g H) and the PPE's right-hand side so small that the run goes on
// with p = 0 (docs/reliability.md).
const ScalarParameter rho = properties.scalar("rho", dim::density, "density").required().above(0).saneMin(1e-3);
const ScalarParameter nu = properties.scalar("nu", dim::kinematicViscosity, "kinematic viscosity (0: no viscous term is built)")
    .def(0).min(0);
// Absent: the water is incompressible (eq. 6). Present: the pressure equation's implicit
// compressibility term, eq. 6c (docs/method.md 4.1).
const ScalarParameter soundSpeed = properties.scalar("soundSpeed", dim::velocity,
    "sound speed of the pressure equation's compressibility term, eq. 6c").shownDefault("absent: incompressible").above(0);
const OptionParameter wallCondition = properties.option("wallCondition", {"noSlip", "slip"},
    "what the walls show the viscous term: the no-slip mirror velocity or free slip (slip, and only slip, with wallFriction)").def("noSlip");
const ParameterGroup gravity("constant/g", "Gravity (file absent: no body force is built).");
const VectorParameter g = gravity.vector("value", dim::acceleration, "gravitational acceleration").required();
}  // namespace key
}  // namespace

PhysicalProperties readPhysicalProperties(const Dictionary& d) {
  PhysicalProperties p;
  p.rho = key::rho.read(d);
  p.nu = key::nu.read(d);
  if (d.subDictPtr("wallFriction")) {
    // The law of the wall gives the walls' whole stress (WallFriction.cpp): the viscous term
    // sees free-slip walls, and a no-slip mirror would add the laminar stress a second time.
    if (d.found("wallCondition") && key::wallCondition.read(d) == "noSlip")
      d.error("wallCondition", "wallFriction gives the walls' shear stress; with it the viscous term needs "
                               "wallCondition slip (the default)");
    d.markRead("wallCondition");
    p.walls = WallVelocity::freeSlip;
  } else {
    p.walls = key::wallCondition.read(d) == "noSlip" ? WallVelocity::noSlip : WallVelocity::freeSlip;
  }
  return p;
}

double readSoundSpeed(const Dictionary& d) { return key::soundSpeed.read(d); }

template <int D>
Vec<D> readGravity(const Dictionary& g) {
  return key::g.read<D>(g);
}

template Vec<2> readGravity<2>(const Dictionary&);
template Vec<3> readGravity<3>(const Dictionary&);

}  // namespace shizuku
