// Test helper: a case directory in a fresh temporary folder, written from
// strings, removed when the object goes out of scope.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

namespace shizuku::test {

// A D-dimensional vector as a dictionary entry, "(a b)" or "(a b c)": c is dropped in 2D.
template <int D>
std::string vec(double a, double b, double c) {
  return "(" + std::to_string(a) + " " + std::to_string(b) + (D == 3 ? " " + std::to_string(c) : "") + ")";
}

class TempCase {
 public:
  explicit TempCase(const std::string& tag) {
    std::string tmpl = (std::filesystem::temp_directory_path() / ("shizuku-" + tag + "-XXXXXX")).string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    dir_ = tmpl;
    std::filesystem::create_directories(dir_ + "/system");
    std::filesystem::create_directories(dir_ + "/constant");
  }
  ~TempCase() {
    if (!std::getenv("SHIZUKU_KEEP_TEST_CASES")) std::filesystem::remove_all(dir_);
  }
  TempCase& file(const std::string& relative, const std::string& text) {
    const auto p = std::filesystem::path(dir_) / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return *this;
  }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
};

}  // namespace shizuku::test
