// Command-line parsing shared by every Shizuku program: Boost.ProgramOptions
// with OpenFOAM-style single-dash long options (`-case DIR` as well as
// `--case DIR`), one error format and one -help behaviour.
// Programs that use it link Boost::program_options.
#pragma once
#include <algorithm>
#include <boost/program_options.hpp>
#include <iostream>
#include <omp.h>
#include <optional>
#include <string>

namespace shizuku {

// Parse into `vm`. Returns an exit status when the program should stop now
// (1: bad option, printed with the option list; 0: -help printed), else nullopt.
// `required` names an option that must be given unless -help is.
inline std::optional<int> parseCommandLine(int argc, char** argv, const std::string& program,
                                           const boost::program_options::options_description& desc,
                                           boost::program_options::variables_map& vm,
                                           const std::string& helpFooter = "",
                                           const std::string& required = "") {
  namespace po = boost::program_options;
  try {
    const auto style = po::command_line_style::default_style | po::command_line_style::allow_long_disguise;
    po::store(po::command_line_parser(argc, argv).options(desc).style(style).run(), vm);
    po::notify(vm);
    if (!required.empty() && !vm.count("help") && !vm.count(required))
      throw std::runtime_error("-" + required + " is required");
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n\n" << desc << "\n";
    return 1;
  }
  if (vm.count("help")) {
    std::cout << desc << "\n" << helpFooter;
    return 0;
  }
  return std::nullopt;
}

// The largest -threads accepted: four times the hardware threads (oversubscription
// beyond that only slows a run down, and 1e5 threads crash the OpenMP runtime), and
// never above the runtime's own limit (OMP_THREAD_LIMIT).
inline int maxThreads() { return std::max(1, std::min(4 * omp_get_num_procs(), omp_get_thread_limit())); }

// The -threads option (declared without a default: absent means OMP_NUM_THREADS or all
// cores): checked to lie in 1 .. maxThreads() and applied. Returns 1 after printing an
// error naming the option, else nullopt.
inline std::optional<int> applyThreadsOption(const boost::program_options::variables_map& vm,
                                             const std::string& program) {
  if (!vm.count("threads")) return std::nullopt;
  const int n = vm["threads"].as<int>();
  if (n < 1 || n > maxThreads()) {
    std::cerr << program << ": option -threads " << n << " is out of range: give 1 to " << maxThreads()
              << " (four times the " << omp_get_num_procs() << " hardware threads)\n";
    return 1;
  }
  omp_set_num_threads(n);
  return std::nullopt;
}

}  // namespace shizuku
