// Building one function object by type name (docs/design.md 1.3), for the list
// factory createFunctionObjects() and for shizukuPostProcess (which may name a
// type with default settings instead of an entry of the controlDict).
// Types: probes densityError conservation fluidExtent flux wallPressure timing.
// Reads (controlDict functions/<name>): type, then the keys of that type.
#pragma once
#include "functionObjects/FunctionObject.hpp"

namespace shizuku {

std::vector<std::string> functionObjectTypes();

// Build the object `name` from its dictionary (which holds `type`); `walls`: the case's
// wall regions (a wallPressure needs its wall's), `gravity` the case's g. Throws InputError.
template <int D>
std::unique_ptr<FunctionObject<D>> createFunctionObject(const std::string& name, const Dictionary& dict,
                                                        const std::vector<WallBox<D>>& walls = {},
                                                        const Vec<D>& gravity = Vec<D>::Zero());

}  // namespace shizuku
