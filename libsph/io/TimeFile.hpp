// <time>/uniform/time: the time state of a time directory (docs/design.md 1.3),
// in the case-dictionary syntax (docs/design.md 1.2), e.g.
//   value    0.1;       // s, exact (shortest text that reads back bit for bit)
//   name     "0.1";     // the directory name
//   index    1000;      // time-step index
//   deltaT   0.0001;    // s, dt of the next step
//   deltaT0  0.0001;    // s, dt of the previous step
//   note     "...";     // optional free text
//   removedMass 0.5;    // optional: fluid removed through the domain's bounds so far
//   removedCount 12;    // optional: particles removed so far
//   released 400;       // optional: particles inlets released so far
//   captured 380;       // optional: particles outlets took so far
// A restart (startFrom latestTime) reads it back and continues exactly.
// This small reader understands only this flat form (keyword value;) plus
// comments; unknown keywords are ignored so later versions can add some.
// Dictionary keys read: value, name, index, deltaT, deltaT0, note, removedMass, removedCount,
// released, captured.
#pragma once
#include "io/TimeDirectory.hpp"
#include <string>

namespace shizuku {

std::string formatTimeFile(const TimeState& s, const std::string& timeName);
// Throws InputError naming the file, line and keyword if it is missing, a
// required entry (value, index, deltaT) is absent or not a number, value is
// not finite, index is negative, or deltaT/deltaT0 is not finite and positive
// (0 is allowed at index 0: the initial state). deltaT0 defaults to deltaT.
// With a folderName, value (and name, if given) must name that folder at the
// writer's precision (timeName(value) reads back as the same number).
TimeState readTimeFile(const std::string& path, const std::string& folderName = "");

}  // namespace shizuku
