// Names of time directories (docs/design.md 1.2, 1.3) and exact number text.
//
// timeName(t, p) is t in the C "%g" general format with p significant digits
// (default 8), trailing zeros removed: 0 -> "0", 0.1 -> "0.1", 1e-4 -> "0.0001",
// 1e-5 -> "1e-05", 1234.5 -> "1234.5", 0.30000000000000004 -> "0.3". Exponent
// notation is used when the decimal exponent is < -4 or >= p, exactly as
// printf/OpenFOAM's general format; it is locale independent. Two times that
// agree to p significant digits share a name (the later write replaces the
// earlier one).
//
// parseTimeName() turns a directory name back into a time: the whole name must
// be a finite decimal number (digits, '.', 'e', 'E', '+', '-'), so "system",
// "0.1.tmp-42" or "inf" are not times.
//
// exactNumber(v) is the shortest decimal text that reads back to exactly v
// (at most 17 significant digits), used wherever a restart must be exact.
// Dictionary keys read: none (the solver passes writePrecision if it has one).
#pragma once
#include <optional>
#include <string>

namespace shizuku {

std::string timeName(double t, int precision = 8);
std::optional<double> parseTimeName(const std::string& name);
std::string exactNumber(double v);
// Parse a whole string as a double (locale independent); nullopt if any
// character is left over or the text is empty.
std::optional<double> parseNumber(const std::string& text);

}  // namespace shizuku
