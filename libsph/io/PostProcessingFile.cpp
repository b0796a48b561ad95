// Function-object output file: see PostProcessingFile.hpp (docs/design.md 1.3).
#include "io/PostProcessingFile.hpp"
#include "io/FileOps.hpp"
#include "parallel/Communicator.hpp"
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace shizuku {

PostProcessingFile::PostProcessingFile(const std::string& caseDir, const std::string& name,
                                       const std::string& startTimeName, const std::string& fileName) {
  if (name.empty() || startTimeName.empty() || fileName.empty())
    throw std::runtime_error("PostProcessingFile: empty name, start time or file name");
  path_ = caseDir + "/postProcessing/" + name + "/" + startTimeName + "/" + fileName;
  // In a distributed run every rank computes the same rows; rank 0 writes them.
  if (!Communicator::world().isRoot()) return;
  fileops::makeDirectories(fileops::parentOf(path_));
  errno = 0;
  file_ = std::fopen(path_.c_str(), "w");
  if (!file_) fileops::throwError("cannot create file", path_, errno);
}

PostProcessingFile::~PostProcessingFile() {
  if (file_) std::fclose(file_);
}

PostProcessingFile::PostProcessingFile(PostProcessingFile&& o) noexcept : path_(std::move(o.path_)), file_(o.file_) {
  o.file_ = nullptr;
}

PostProcessingFile& PostProcessingFile::operator=(PostProcessingFile&& o) noexcept {
  if (this != &o) {
    if (file_) std::fclose(file_);
    path_ = std::move(o.path_);
    file_ = o.file_;
    o.file_ = nullptr;
  }
  return *this;
}

void PostProcessingFile::put(const std::string& text) {
  if (!Communicator::world().isRoot()) return;
  if (!file_) throw std::runtime_error("PostProcessingFile: '" + path_ + "' is not open");
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
    fileops::throwError("cannot write", path_, errno ? errno : EIO);
}

void PostProcessingFile::comment(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    std::size_t end = text.find('\n', start);
    out += "# " + text.substr(start, end == std::string::npos ? std::string::npos : end - start) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  put(out);
}

void PostProcessingFile::columns(const std::vector<std::string>& names, const std::vector<std::string>& units) {
  if (names.size() != units.size())
    throw std::runtime_error("PostProcessingFile '" + path_ + "': " + std::to_string(names.size()) +
                             " column names but " + std::to_string(units.size()) + " units");
  std::string a = "# columns:", b = "# units:  ";
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::size_t w = std::max(names[k].size(), units[k].size());
    a += " " + names[k] + std::string(w - names[k].size(), ' ');
    b += " " + units[k] + std::string(w - units[k].size(), ' ');
  }
  while (!a.empty() && a.back() == ' ') a.pop_back();
  while (!b.empty() && b.back() == ' ') b.pop_back();
  put(a + "\n" + b + "\n");
}

void PostProcessingFile::row(const std::string& text) { put(text + "\n"); }

void PostProcessingFile::row(double time, const std::vector<double>& values) {
  std::string s = number(time);
  for (double v : values) s += " " + number(v);
  row(s);
}

std::string PostProcessingFile::number(double v) {
  if (v != v) return "nan";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

}  // namespace shizuku
