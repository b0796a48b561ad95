// One function-object output file (docs/design.md 1.3):
//   <case>/postProcessing/<name>/<startTimeName>/<fileName>
// Folders are created as needed; `#` header lines name the columns and their
// units; then one whitespace-separated row per sample, time first, each row
// flushed at once so the file can be followed while the run goes on.
// Each start time has its own folder, so a restarted run never touches the
// files of earlier start times; a rerun from the same start time replaces its
// own file. fileName may contain '/' (e.g. "histogram/0.1.dat").
// Numbers: 12 significant digits ("%.12g"), nan as "nan"; vectors "(x y)".
// In a distributed run only rank 0 opens and writes the file (every rank computes the
// same rows: docs/parallel.md 5).
// Dictionary keys read: none.
#pragma once
#include "core/types.hpp"
#include <cstdio>
#include <string>
#include <vector>

namespace shizuku {

class PostProcessingFile {
 public:
  // Throws std::runtime_error naming the path and strerror on failure.
  PostProcessingFile(const std::string& caseDir, const std::string& name, const std::string& startTimeName,
                     const std::string& fileName);
  ~PostProcessingFile();
  PostProcessingFile(PostProcessingFile&& o) noexcept;
  PostProcessingFile& operator=(PostProcessingFile&& o) noexcept;
  PostProcessingFile(const PostProcessingFile&) = delete;
  PostProcessingFile& operator=(const PostProcessingFile&) = delete;

  const std::string& path() const { return path_; }

  // "# <text>" (one line per '\n'-separated part).
  void comment(const std::string& text);
  // Two header lines, names and units aligned, e.g.
  //   # columns: time  mean  rms
  //   # units:   s     %     %
  // A vector column is one name (its row entry is "(x y)"). Units "-" for none.
  void columns(const std::vector<std::string>& names, const std::vector<std::string>& units);
  // One row: the text as given, plus '\n'; flushed.
  void row(const std::string& text);
  // One row of numbers: time then values, space separated; flushed.
  void row(double time, const std::vector<double>& values);

  static std::string number(double v);
  template <int D> static std::string vector(const Vec<D>& v) {
    std::string s = "(";
    for (int k = 0; k < D; ++k) s += (k ? " " : "") + number(v[k]);
    return s + ")";
  }

 private:
  void put(const std::string& text);
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace shizuku
