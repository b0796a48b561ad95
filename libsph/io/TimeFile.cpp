// uniform/time writer and reader: see TimeFile.hpp (docs/design.md 1.3).
#include "io/TimeFile.hpp"
#include "io/TimeName.hpp"
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace shizuku {

namespace {

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += (c == '\n' ? ' ' : c);
  }
  return q + "\"";
}

struct Entry {
  std::string text;
  int line = 0;
};

[[noreturn]] void bad(const std::string& path, int line, const std::string& why) {
  throw InputError(path + ":" + std::to_string(line) + ": " + why);
}

// keyword -> value text (strings unquoted), for the flat `keyword value;` form.
std::map<std::string, Entry> parse(const std::string& path, const std::string& text) {
  std::map<std::string, Entry> out;
  std::size_t i = 0;
  int line = 1;
  auto skipSpace = [&] {
    while (i < text.size()) {
      char c = text[i];
      if (c == '\n') { ++line; ++i; }
      else if (std::isspace((unsigned char)c)) ++i;  // the same blanks that end a word below
      else if (text.compare(i, 2, "//") == 0) { while (i < text.size() && text[i] != '\n') ++i; }
      else if (text.compare(i, 2, "/*") == 0) {
        std::size_t end = text.find("*/", i + 2);
        if (end == std::string::npos) bad(path, line, "unterminated /* comment");
        for (std::size_t k = i; k < end; ++k) line += text[k] == '\n';
        i = end + 2;
      } else break;
    }
  };
  auto token = [&](std::string& t, bool& wasString) {
    skipSpace();
    t.clear();
    wasString = false;
    if (i >= text.size()) return false;
    if (text[i] == '"') {
      wasString = true;
      ++i;
      while (i < text.size() && text[i] != '"') {
        if (text[i] == '\\' && i + 1 < text.size()) ++i;
        if (text[i] == '\n') ++line;
        t += text[i++];
      }
      if (i >= text.size()) bad(path, line, "unterminated string");
      ++i;
      return true;
    }
    if (text[i] == ';' || text[i] == '{' || text[i] == '}') { t = text[i++]; return true; }
    while (i < text.size() && !std::isspace((unsigned char)text[i]) && text[i] != ';' && text[i] != '"' &&
           text[i] != '{' && text[i] != '}')
      t += text[i++];
    if (t.empty()) bad(path, line, "unexpected character");  // never loop without progress
    return true;
  };
  std::string key, value, semi;
  bool s1, s2, s3;
  while (token(key, s1)) {
    int at = line;
    if (key == "{" || key == ";" || key == "}") bad(path, at, "unexpected '" + key + "'");
    if (!token(value, s2)) bad(path, at, "keyword '" + key + "' has no value");
    if (value == "{") {  // a header block such as FoamFile { ... }: skipped
      int depth = 1;
      while (depth > 0 && token(value, s2)) depth += (value == "{") - (value == "}");
      if (depth > 0) bad(path, at, "unterminated block '" + key + "'");
      continue;
    }
    if (!token(semi, s3) || semi != ";") bad(path, at, "keyword '" + key + "': expected ';' after the value");
    out[key] = Entry{value, at};
  }
  return out;
}

double number(const std::string& path, const std::map<std::string, Entry>& e, const std::string& key) {
  auto it = e.find(key);
  if (it == e.end()) throw InputError(path + ": keyword '" + key + "' is missing");
  auto v = parseNumber(it->second.text);
  if (!v) bad(path, it->second.line, "keyword '" + key + "': '" + it->second.text + "' is not a number");
  return *v;
}

// The folder's name, the time it holds and the `name` keyword agree to the
// writer's time-name precision (TimeName.hpp): a folder renamed or copied to
// another time is refused, not listed and run at the wrong time.
void checkFolderName(const std::string& path, const std::map<std::string, Entry>& e, double time,
                     const std::string& folderName) {
  const auto folder = parseTimeName(folderName);
  const std::string expected = timeName(time);
  if (!folder || *folder != *parseTimeName(expected))
    bad(path, e.at("value").line, "keyword 'value': time " + exactNumber(time) + " does not belong in folder '" +
                                      folderName + "' (its folder is '" + expected + "')");
  auto it = e.find("name");
  if (it != e.end() && parseTimeName(it->second.text) != folder)
    bad(path, it->second.line, "keyword 'name': '" + it->second.text + "' is not the folder's name '" + folderName + "'");
}

// An optional whole number >= 0 (0 when absent).
long count(const std::string& path, const std::map<std::string, Entry>& e, const char* key) {
  if (!e.count(key)) return 0;
  const double n = number(path, e, key);
  if (!(n >= 0 && n <= 9e15 && n == std::floor(n)))
    bad(path, e.at(key).line, std::string("keyword '") + key + "': " + exactNumber(n) + " is not a whole number >= 0");
  return long(n);
}

}  // namespace

std::string formatTimeFile(const TimeState& s, const std::string& timeName) {
  std::ostringstream o;
  o << "/*--------------------------------------------------------------------------*\\\n"
       "  shizuku: time state of time directory " << timeName << "\n"
       "  Read back on restart (startFrom latestTime); numbers are exact.\n"
       "\\*--------------------------------------------------------------------------*/\n\n";
  o << "value    " << exactNumber(s.time) << ";   // s\n";
  o << "name     " << quoted(timeName) << ";\n";
  o << "index    " << s.step << ";\n";
  o << "deltaT   " << exactNumber(s.deltaT) << ";   // s, next step\n";
  o << "deltaT0  " << exactNumber(s.deltaT0) << ";   // s, previous step\n";
  if (!s.note.empty()) o << "note     " << quoted(s.note) << ";\n";
  const FluidBalance& b = s.balance;
  if (b.removedCount > 0) {
    o << "removedMass   " << exactNumber(b.removedMass) << ";   // fluid removed through the domain's bounds\n";
    o << "removedCount  " << b.removedCount << ";\n";
  }
  if (b.released > 0) o << "released      " << b.released << ";   // particles released by inlets\n";
  if (b.captured > 0) o << "captured      " << b.captured << ";   // particles taken by outlets\n";
  return o.str();
}

TimeState readTimeFile(const std::string& path, const std::string& folderName) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read time file '" + path + "': " + std::strerror(errno));
  std::stringstream buf;
  buf << in.rdbuf();
  auto e = parse(path, buf.str());
  TimeState s;
  s.time = number(path, e, "value");
  if (!std::isfinite(s.time)) bad(path, e.at("value").line, "keyword 'value': " + exactNumber(s.time) + " is not a finite time");
  auto it = e.find("index");
  if (it == e.end()) throw InputError(path + ": keyword 'index' is missing");
  const std::string& t = it->second.text;
  auto r = std::from_chars(t.data(), t.data() + t.size(), s.step);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size())
    bad(path, it->second.line, "keyword 'index': '" + t + "' is not an integer");
  if (s.step < 0) bad(path, it->second.line, "keyword 'index': " + t + " is negative (a time-step index is >= 0)");
  s.deltaT = number(path, e, "deltaT");
  s.deltaT0 = e.count("deltaT0") ? number(path, e, "deltaT0") : s.deltaT;
  for (const char* k : {"deltaT", "deltaT0"}) {
    const double dt = std::string(k) == "deltaT" ? s.deltaT : s.deltaT0;
    // 0 only in the initial state, written before any step chose a dt.
    if (!std::isfinite(dt) || dt < 0 || (dt == 0 && s.step != 0))
      bad(path, e.at(e.count(k) ? k : "deltaT").line,
          std::string("keyword '") + k + "': " + exactNumber(dt) + " is not a positive finite time step");
  }
  if (e.count("note")) s.note = e.at("note").text;
  FluidBalance& b = s.balance;
  if (e.count("removedMass")) b.removedMass = number(path, e, "removedMass");
  if (!std::isfinite(b.removedMass) || b.removedMass < 0)
    bad(path, e.at("removedMass").line, "keyword 'removedMass': " + exactNumber(b.removedMass) + " is not a mass >= 0");
  b.removedCount = count(path, e, "removedCount");
  b.released = count(path, e, "released");
  b.captured = count(path, e, "captured");
  if (!folderName.empty()) checkFolderName(path, e, s.time, folderName);
  return s;
}

}  // namespace shizuku
