// Command-line parsing shared by every Shizuku program: Boost.ProgramOptions
// with OpenFOAM-style single-dash long options (`-case DIR` as well as
// `--case DIR`), one error format and one -help behaviour.
// Programs that use it link Boost::program_options.
#pragma once
#include <boost/program_options.hpp>
#include <iostream>
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

}  // namespace shizuku
