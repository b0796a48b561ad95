// The run log: everything the solver tells the user goes through here, to
// standard output (and optionally a file), line buffered. In a distributed run only
// rank 0 speaks (`silent` on the others): every rank reads the same case and reaches
// the same decisions, so one voice reports them once.
#pragma once
#include <iostream>
#include <sstream>
#include <string>

namespace shizuku {

class Log {
 public:
  static Log& get() { static Log l; return l; }
  void line(const std::string& s) { if (!silent) std::cout << s << '\n' << std::flush; }
  void warning(const std::string& s) { if (!silent) std::cout << "Warning: " << s << '\n' << std::flush; }
  void error(const std::string& s) { if (!silent) std::cerr << "Error: " << s << '\n' << std::flush; }
  bool quiet = false;   // progress and information off (errors and warnings still shown)
  bool silent = false;  // nothing at all (the ranks other than 0)
};

// Format helper: fmt("dt = ", dt) -> "dt = 1e-4"
template <class... A> std::string cat(const A&... a) {
  std::ostringstream os;
  (os << ... << a);
  return os.str();
}

inline void info(const std::string& s) { if (!Log::get().quiet) Log::get().line(s); }

}  // namespace shizuku
