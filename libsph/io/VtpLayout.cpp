// particles.vtp pre-scan: see VtpLayout.hpp (docs/reliability.md).
#include "io/VtpLayout.hpp"
#include "core/types.hpp"
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <vector>

namespace shizuku {

[[noreturn]] void corruptVtp(const std::string& path, const std::string& why) {
  throw InputError("corrupt particle file '" + path + "': " + why);
}

namespace {

constexpr std::size_t kMaxHeader = 1 << 20;         // bytes of XML before the appended data
constexpr std::int64_t kMaxCount = std::int64_t(1) << 48;  // values of one array; no file is that big
const char kMarker[] = "<AppendedData encoding=\"raw\">";

struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  bool closing = false;      // </name>
  bool selfClosing = false;  // <name ... />
};

struct Array {
  std::string parent, name;
  std::map<std::string, std::string> attrs;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.';
}

// The markup of the XML header, one element tag at a time; comments and the
// <?xml ...?> declaration are skipped, anything else that is not a plain tag
// (DOCTYPE, entities, text) is refused.
class HeaderScanner {
 public:
  HeaderScanner(const std::string& path, const std::string& text) : path_(path), text_(text) {}

  bool next(Element& e) {
    for (;;) {
      while (i_ < text_.size() && isSpace(text_[i_])) ++i_;
      if (i_ >= text_.size()) return false;
      if (text_[i_] != '<') fail("text outside a tag");
      if (text_.compare(i_, 4, "<!--") == 0) { skipPast("-->"); continue; }
      if (text_.compare(i_, 5, "<?xml") == 0 && !seenElement_) { skipPast("?>"); continue; }
      if (text_.compare(i_, 2, "<!") == 0 || text_.compare(i_, 2, "<?") == 0)
        fail("unexpected '" + text_.substr(i_, 9) + "' (a particles.vtp has only plain elements)");
      seenElement_ = true;
      tag(e);
      return true;
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    corruptVtp(path_, "XML header, byte " + std::to_string(i_) + ": " + why);
  }
  void skipPast(const char* end) {
    const std::size_t at = text_.find(end, i_);
    if (at == std::string::npos) fail(std::string("no closing '") + end + "'");
    i_ = at + std::strlen(end);
  }
  std::string name() {
    const std::size_t start = i_;
    while (i_ < text_.size() && isNameChar(text_[i_])) ++i_;
    if (i_ == start) fail("expected a name");
    return text_.substr(start, i_ - start);
  }
  void skipSpace() {
    while (i_ < text_.size() && isSpace(text_[i_])) ++i_;
    if (i_ >= text_.size()) fail("the header ends inside a tag");
  }
  void tag(Element& e) {
    e = Element();
    ++i_;  // '<'
    if (i_ < text_.size() && text_[i_] == '/') {
      ++i_;
      e.closing = true;
      e.name = name();
      skipSpace();
      if (text_[i_] != '>') fail("expected '>' after </" + e.name);
      ++i_;
      return;
    }
    e.name = name();
    for (;;) {
      skipSpace();
      if (text_[i_] == '>') { ++i_; return; }
      if (text_.compare(i_, 2, "/>") == 0) { i_ += 2; e.selfClosing = true; return; }
      const std::string key = name();
      skipSpace();
      if (text_[i_] != '=') fail("attribute '" + key + "' of <" + e.name + "> has no value");
      ++i_;
      skipSpace();
      const char quote = text_[i_];
      if (quote != '"' && quote != '\'') fail("attribute '" + key + "' of <" + e.name + "> is not quoted");
      const std::size_t end = text_.find(quote, ++i_);
      if (end == std::string::npos) fail("attribute '" + key + "' of <" + e.name + "> is not closed");
      std::string value = text_.substr(i_, end - i_);
      if (value.find_first_of("<&") != std::string::npos)
        fail("attribute '" + key + "' of <" + e.name + "> holds '<' or '&'");
      if (!e.attrs.emplace(key, std::move(value)).second) fail("attribute '" + key + "' of <" + e.name + "> repeated");
      i_ = end + 1;
    }
  }

  const std::string& path_;
  const std::string& text_;
  std::size_t i_ = 0;
  bool seenElement_ = false;
};

std::int64_t count(const std::string& path, const std::string& what, const std::string& text) {
  std::int64_t v = -1;
  auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || v < 0 || v > kMaxCount)
    corruptVtp(path, what + " is '" + text + "', not a count (a whole number 0 to 2^48)");
  return v;
}

int typeSize(const std::string& type) {
  static const std::map<std::string, int> sizes = {{"Int8", 1},  {"UInt8", 1},  {"Int16", 2},   {"UInt16", 2},
                                                   {"Int32", 4}, {"UInt32", 4}, {"Int64", 8},   {"UInt64", 8},
                                                   {"Float32", 4}, {"Float64", 8}};
  auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// Which element may hold which (the tree VtpFile writes).
const std::map<std::string, std::set<std::string>>& allowedChildren() {
  static const std::map<std::string, std::set<std::string>> m = {
      {"", {"VTKFile"}},
      {"VTKFile", {"PolyData"}},
      {"PolyData", {"FieldData", "Piece"}},
      {"Piece", {"PointData", "CellData", "Points", "Verts", "Lines", "Strips", "Polys"}},
      {"FieldData", {"DataArray"}}, {"PointData", {"DataArray"}}, {"CellData", {"DataArray"}},
      {"Points", {"DataArray"}},    {"Verts", {"DataArray"}},     {"Lines", {"DataArray"}},
      {"Strips", {"DataArray"}},    {"Polys", {"DataArray"}}};
  return m;
}

std::string attr(const Element& e, const std::string& key) {
  auto it = e.attrs.find(key);
  return it == e.attrs.end() ? std::string() : it->second;
}

void checkRoot(const std::string& path, const Element& e) {
  auto want = [&](const char* key, const char* value) {
    if (attr(e, key) != value)
      corruptVtp(path, std::string("<VTKFile> attribute ") + key + " is '" + attr(e, key) + "', expected '" + value + "'");
  };
  want("type", "PolyData");
  want("byte_order", "LittleEndian");
  want("header_type", "UInt64");
  if (e.attrs.count("compressor")) corruptVtp(path, "<VTKFile> is compressed (a restart file is raw)");
}

// The XML header: the element tree, the Piece counts and the arrays.
struct Header {
  std::int64_t points = -1, verts = 0, otherCells = 0;
  std::vector<Array> arrays;
  int pointsArrays = 0;
};

Header scanHeader(const std::string& path, const std::string& text) {
  Header h;
  HeaderScanner scan(path, text);
  std::vector<std::string> open;  // element stack
  std::set<std::string> seenInPiece;
  Element e;
  while (scan.next(e)) {
    if (e.closing) {
      if (open.empty() || open.back() != e.name) corruptVtp(path, "XML header: unexpected </" + e.name + ">");
      open.pop_back();
      continue;
    }
    const std::string parent = open.empty() ? "" : open.back();
    const auto& allowed = allowedChildren().at(parent);
    if (!allowed.count(e.name))
      corruptVtp(path, "XML header: <" + e.name + "> inside " + (parent.empty() ? "the file" : "<" + parent + ">"));
    if (parent == "Piece" && !seenInPiece.insert(e.name).second) corruptVtp(path, "XML header: two <" + e.name + ">");
    if (e.name == "VTKFile") checkRoot(path, e);
    if (e.name == "Piece") {
      if (h.points >= 0) corruptVtp(path, "XML header: more than one <Piece>");
      h.points = count(path, "<Piece> NumberOfPoints", attr(e, "NumberOfPoints"));
      h.verts = count(path, "<Piece> NumberOfVerts", attr(e, "NumberOfVerts"));
      for (const char* k : {"NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        if (e.attrs.count(k)) h.otherCells += count(path, std::string("<Piece> ") + k, attr(e, k));
    }
    if (e.name == "DataArray") {
      if (!e.selfClosing) corruptVtp(path, "XML header: <DataArray Name=\"" + attr(e, "Name") + "\"> holds inline data");
      h.arrays.push_back(Array{parent, attr(e, "Name"), e.attrs});
      h.pointsArrays += parent == "Points";
    } else if (!e.selfClosing) {
      open.push_back(e.name);
    }
    if (open.size() > 8) corruptVtp(path, "XML header: nested too deep");
  }
  // <AppendedData> follows inside <VTKFile>, after everything else is closed.
  if (open != std::vector<std::string>{"VTKFile"})
    corruptVtp(path, "XML header: " + (open.empty() ? std::string("<AppendedData> is outside <VTKFile>")
                                                    : "<" + open.back() + "> is not closed before the appended data"));
  if (h.points < 0) corruptVtp(path, "XML header: no <Piece>");
  if (h.verts != h.points || h.otherCells != 0)
    corruptVtp(path, "<Piece> has NumberOfVerts " + std::to_string(h.verts) + " and " + std::to_string(h.otherCells) +
                         " other cells for NumberOfPoints " + std::to_string(h.points) +
                         " (a particles.vtp has one vertex per point and nothing else)");
  if (h.pointsArrays != 1) corruptVtp(path, "<Points> must hold exactly one DataArray");
  return h;
}

// How many tuples the array's place in the tree implies.
std::int64_t expectedTuples(const std::string& path, const Header& h, const Array& a, const std::string& what) {
  if (a.parent == "FieldData") {
    if (!a.attrs.count("NumberOfTuples")) corruptVtp(path, what + " has no NumberOfTuples");
    return count(path, what + " NumberOfTuples", a.attrs.at("NumberOfTuples"));
  }
  std::int64_t n = 0;
  if (a.parent == "PointData" || a.parent == "Points") n = h.points;
  else if (a.parent == "CellData" || a.parent == "Verts") n = h.verts;
  if (a.parent == "Verts" || a.parent == "Lines" || a.parent == "Strips" || a.parent == "Polys")
    if (a.name != "connectivity" && a.name != "offsets") corruptVtp(path, what + " is not connectivity or offsets");
  if (a.attrs.count("NumberOfTuples") && count(path, what + " NumberOfTuples", a.attrs.at("NumberOfTuples")) != n)
    corruptVtp(path, what + " has NumberOfTuples " + a.attrs.at("NumberOfTuples") + ", expected " + std::to_string(n));
  return n;
}

class FileBytes {
 public:
  explicit FileBytes(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw InputError("cannot read particle file '" + path + "': " + std::strerror(errno));
    in_.seekg(0, std::ios::end);
    size_ = std::int64_t(in_.tellg());
    in_.seekg(0);
  }
  std::int64_t size() const { return size_; }
  std::string read(std::int64_t at, std::int64_t n) {
    std::string s(std::size_t(std::max<std::int64_t>(0, std::min(n, size_ - at))), '\0');
    in_.seekg(at);
    if (!in_.read(s.data(), std::streamsize(s.size()))) corruptVtp(path_, "read error at byte " + std::to_string(at));
    return s;
  }

 private:
  const std::string& path_;
  std::ifstream in_;
  std::int64_t size_ = 0;
};

std::vector<std::int64_t> int64Values(const std::string& bytes) {
  std::vector<std::int64_t> v(bytes.size() / 8);
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * 8);
  return v;
}

// One vertex per point: offsets 1..n, each connectivity entry a point index.
void checkVerts(const std::string& path, const std::vector<std::int64_t>& offsets,
                const std::vector<std::int64_t>& connectivity, std::int64_t points) {
  if (std::int64_t(offsets.size()) != points || std::int64_t(connectivity.size()) != points)
    corruptVtp(path, "<Verts> lacks its offsets or connectivity array");
  for (std::size_t i = 0; i < offsets.size(); ++i)
    if (offsets[i] != std::int64_t(i) + 1)
      corruptVtp(path, "<Verts> offsets[" + std::to_string(i) + "] is " + std::to_string(offsets[i]) + ", expected " +
                           std::to_string(i + 1));
  for (std::size_t i = 0; i < connectivity.size(); ++i)
    if (connectivity[i] < 0 || connectivity[i] >= points)
      corruptVtp(path, "<Verts> connectivity[" + std::to_string(i) + "] is " + std::to_string(connectivity[i]) +
                           ", not a point index below " + std::to_string(points));
}

void checkTail(const std::string& path, const std::string& tail) {
  std::size_t i = 0;
  auto expect = [&](const char* word) {
    while (i < tail.size() && isSpace(tail[i])) ++i;
    if (tail.compare(i, std::strlen(word), word) != 0)
      corruptVtp(path, std::string("after the last data block: expected ") + word + " (cut short, or bytes added)");
    i += std::strlen(word);
  };
  expect("</AppendedData>");
  expect("</VTKFile>");
  while (i < tail.size() && isSpace(tail[i])) ++i;
  if (i != tail.size()) corruptVtp(path, "bytes after </VTKFile>");
}

}  // namespace

VtpLayout scanVtpLayout(const std::string& path) {
  FileBytes file(path);
  const std::string head = file.read(0, std::int64_t(kMaxHeader));
  const std::size_t marker = head.find(kMarker);
  if (marker == std::string::npos)
    corruptVtp(path, std::string("no ") + kMarker + " in its first MiB (a particles.vtp holds raw appended data)");
  std::size_t start = marker + sizeof kMarker - 1;
  while (start < head.size() && isSpace(head[start])) ++start;
  if (start >= head.size() || head[start] != '_') corruptVtp(path, "appended data does not start with '_'");
  ++start;
  const Header h = scanHeader(path, head.substr(0, marker));

  std::int64_t end = std::int64_t(start);
  std::map<std::string, std::vector<std::int64_t>> verts;
  for (const Array& a : h.arrays) {
    const std::string what = "array '" + a.name + "' (<" + a.parent + ">)";
    auto get = [&](const char* k) { return a.attrs.count(k) ? a.attrs.at(k) : std::string(); };
    const int size = typeSize(get("type"));
    if (size == 0) corruptVtp(path, what + " has type '" + get("type") + "', not a numeric VTK type");
    if (get("format") != "appended") corruptVtp(path, what + " is not in the appended data (format '" + get("format") + "')");
    const std::int64_t components = a.attrs.count("NumberOfComponents")
                                        ? count(path, what + " NumberOfComponents", get("NumberOfComponents")) : 1;
    if (components < 1 || components > 9) corruptVtp(path, what + " has " + std::to_string(components) + " components");
    if (a.parent == "Points" && components != 3) corruptVtp(path, what + " has " + std::to_string(components) + " components, expected 3");
    if (a.parent == "Verts" && (get("type") != "Int64" || components != 1)) corruptVtp(path, what + " is not one Int64 per vertex");
    const std::int64_t tuples = expectedTuples(path, h, a, what);
    const std::int64_t bytes = tuples * components * size;
    const std::int64_t at = std::int64_t(start) + count(path, what + " offset", get("offset"));
    if (at + 8 > file.size()) corruptVtp(path, what + " starts past the end of the file (cut short?)");
    std::uint64_t stored = 0;
    std::memcpy(&stored, file.read(at, 8).data(), 8);
    if (stored != std::uint64_t(bytes))
      corruptVtp(path, what + " holds " + std::to_string(stored) + " bytes, expected " + std::to_string(bytes) + " (" +
                           std::to_string(tuples) + " values x " + std::to_string(components) + " x " +
                           std::to_string(size) + " bytes" + (a.parent == "FieldData" ? ")" : "; NumberOfPoints is " + std::to_string(h.points) + ")"));
    if (at + 8 + bytes > file.size()) corruptVtp(path, what + " ends past the end of the file (cut short?)");
    end = std::max(end, at + 8 + bytes);
    if (a.parent == "Verts") verts[a.name] = int64Values(file.read(at + 8, bytes));
  }
  checkVerts(path, verts["offsets"], verts["connectivity"], h.points);
  if (file.size() - end > 4096) corruptVtp(path, std::to_string(file.size() - end) + " bytes after the last data block");
  checkTail(path, file.read(end, file.size() - end));
  return VtpLayout{h.points};
}

}  // namespace shizuku
