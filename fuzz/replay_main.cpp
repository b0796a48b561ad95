// Corpus replay: runs a fuzz target's LLVMFuzzerTestOneInput on every file
// named on the command line (folders: every file in them, sorted), so the
// committed corpus, and every crash the fuzzer ever found, stays a test
// without libFuzzer. Prints "<target>: N inputs replayed" and exits 0; a bug
// aborts or crashes the program (ctest reports it as a failure).
//
//   fuzz_dictionary_replay fuzz/corpus/dictionary fuzz/crashes/dictionary
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <omp.h>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  omp_set_num_threads(1);
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p(argv[i]);
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (fs::is_regular_file(p)) {
      files.push_back(p);
    } else {
      std::cerr << "replay: no such file or folder: " << p << "\n";
      return 1;
    }
  }
  std::sort(files.begin(), files.end());
  // What the code under test logs (warnings) is not the test's output.
  std::streambuf* out = std::cout.rdbuf();
  std::ostringstream discard;
  std::cout.rdbuf(discard.rdbuf());
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (std::getenv("SHIZUKU_REPLAY_VERBOSE")) std::cerr << "replay: " << f.string() << "\n";
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    discard.str("");
  }
  std::cout.rdbuf(out);
  std::cout << fs::path(argv[0]).filename().string() << ": " << files.size() << " inputs replayed\n";
  return files.empty() ? 1 : 0;
}
