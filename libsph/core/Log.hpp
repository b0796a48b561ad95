// The run log: everything the solver tells the user goes through here, to
// standard output (and optionally a file), line buffered.
#pragma once
#include <iostream>
#include <sstream>
#include <string>

namespace shizuku {

class Log {
 public:
  static Log& get() { static Log l; return l; }
  void line(const std::string& s) { std::cout << s << '\n' << std::flush; }
  void warning(const std::string& s) { std::cout << "Warning: " << s << '\n' << std::flush; }
  void error(const std::string& s) { std::cerr << "Error: " << s << '\n' << std::flush; }
  bool quiet = false;
};

// Format helper: fmt("dt = ", dt) -> "dt = 1e-4"
template <class... A> std::string cat(const A&... a) {
  std::ostringstream os;
  (os << ... << a);
  return os.str();
}

inline void info(const std::string& s) { if (!Log::get().quiet) Log::get().line(s); }

}  // namespace shizuku
