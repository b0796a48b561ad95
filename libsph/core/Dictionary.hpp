// Reader for case dictionaries: the OpenFOAM-style syntax subset of
// docs/design.md 1.2 (FoamFile header, comments, entries, sub-dictionaries, lists,
// vectors, strings, switches, $macro and $sub/macro, #include,
// #includeIfPresent, units after numbers and vectors).
//
// Every lookup records the keyword as known; after a consumer has read what it
// needs, checkAllRead() turns any keyword nobody asked for into an InputError
// with a "did you mean" suggestion. Every default used is recorded once
// (defaultsUsed()) so the solver can list it in the log.
// Errors are InputError with "file:line:column: keyword 'k': message".
//
// Rules worth knowing (docs/dictionaries.md has the user's version):
// - `keyword v1 v2 ...;` is stored as one list value; a value of several
//   tokens must be written on one line (a list in parentheses may span lines),
//   so that a forgotten ';' is reported at the end of the line it belongs to.
// - A repeated keyword replaces the earlier value (its place in keys() stays);
//   two sub-dictionaries of the same name merge, recursively.
// - `$name` copies an entry defined earlier in this or an enclosing
//   dictionary, `$sub/name` walks into sub-dictionaries, and `$name;` standing
//   alone merges a dictionary into the current one. The entries a macro
//   refers to count as read.
// - A unit written after a list applies to every number in it; numbers are
//   SI after parsing; getters check the unit's dimension (no unit = SI).
#pragma once
#include "core/Dimension.hpp"
#include "core/types.hpp"
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace shizuku {

struct SourceLocation {
  std::string file;
  int line = 0, column = 0;
  std::string includedFrom;  // "" or "FILE:LINE:COLUMN[, included from ...]" of the #include
  std::string str() const;   // "file:line:column" [" (included from FILE:LINE:COLUMN)"]
};

// One parsed value: a token tree.
struct DictValue {
  enum class Kind { word, number, string, list, dict };
  Kind kind = Kind::word;
  std::string text;                  // word / string text, or the number as written
  double number = 0;                 // numeric value in SI (unit applied)
  bool hasUnit = false;
  Dimension unitDim;                 // dimension of the unit, if hasUnit
  std::string unitText;              // the unit as written, without brackets ("cm/s^2")
  std::vector<DictValue> items;      // list items (a unit after a list applies to all numbers)
  std::shared_ptr<class Dictionary> dict;  // kind == dict
  SourceLocation where;
};

class Dictionary {
 public:
  Dictionary() = default;
  // Parse a file; `#include` paths are relative to the including file.
  static Dictionary fromFile(const std::string& path);
  static Dictionary fromString(const std::string& text, const std::string& name = "<string>");
  // Read `path` if it exists, else an empty dictionary named after it.
  static Dictionary fromFileIfPresent(const std::string& path);

  const std::string& name() const { return name_; }  // file path, plus "/sub" scope
  bool empty() const { return order_.empty(); }

  // --- lookups (each marks `key` as known) ----------------------------------
  bool found(const std::string& key) const;
  bool isDict(const std::string& key) const;
  const Dictionary& subDict(const std::string& key) const;        // error if absent / not a dict
  const Dictionary* subDictPtr(const std::string& key) const;     // nullptr if absent
  std::vector<std::string> keys() const;                          // in file order
  const DictValue& value(const std::string& key) const;           // raw value

  double getScalar(const std::string& key, Dimension d) const;
  double getScalarOr(const std::string& key, double def, Dimension d) const;
  int getInt(const std::string& key) const;
  int getIntOr(const std::string& key, int def) const;
  template <int D> Vec<D> getVector(const std::string& key, Dimension d) const;
  template <int D> Vec<D> getVectorOr(const std::string& key, const Vec<D>& def, Dimension d) const;
  std::string getWord(const std::string& key) const;
  std::string getWordOr(const std::string& key, const std::string& def) const;
  // A word that must be one of `options` (error with did-you-mean otherwise).
  std::string getOption(const std::string& key, const std::vector<std::string>& options) const;
  std::string getOptionOr(const std::string& key, const std::vector<std::string>& options,
                          const std::string& def) const;
  bool getSwitch(const std::string& key) const;
  bool getSwitchOr(const std::string& key, bool def) const;
  std::vector<std::string> getWordList(const std::string& key) const;    // (a b c); strings allowed
  std::vector<double> getScalarList(const std::string& key, Dimension d) const;
  template <int D> std::vector<Vec<D>> getVectorList(const std::string& key, Dimension d) const;  // ((..) (..))
  // A D x D matrix written as ((a b) (c d)), row by row.
  template <int D> Mat<D> getMatrix(const std::string& key, Dimension d) const;

  SourceLocation location(const std::string& key) const;  // of the keyword; the dictionary's own if absent
  [[noreturn]] void error(const std::string& key, const std::string& message) const;

  // Recursively: every keyword not looked up is an error naming file, line and
  // the closest known keyword ("did you mean 'maxCo'?").
  void checkAllRead() const;
  // Mark a keyword known without reading it (e.g. the FoamFile header).
  void markRead(const std::string& key) const;
  // Mark every keyword, recursively, known (a dictionary deliberately ignored,
  // e.g. `functions` under -noFunctionObjects).
  void markAllRead() const;

  // "file: key default value" lines, each default once, in the order used.
  static std::vector<std::string>& defaultsUsed();

 private:
  friend class DictionaryParser;
  std::string name_;
  SourceLocation where_;
  std::vector<std::string> order_;
  std::map<std::string, DictValue> entries_;
  std::map<std::string, SourceLocation> keyLocation_;
  mutable std::set<std::string> queried_;
  void recordDefault(const std::string& key, const std::string& value) const;
  const DictValue* find(const std::string& key) const;  // marks key; nullptr if absent
  const DictValue& require(const std::string& key, const std::string& expected) const;
  double numberOf(const std::string& key, const DictValue& v, Dimension d) const;
  template <int D> Vec<D> vectorOf(const std::string& key, const DictValue& v, Dimension d) const;
};

// A number or a vector as the messages, the log and the keyword tables print it: 10
// significant digits, round numbers far from 1 as powers of ten ("0.001", "1e-8", "1e12").
std::string formatNumber(double x);
template <int D> std::string formatNumber(const Vec<D>& v) {
  std::string s = "(";
  for (int k = 0; k < D; ++k) s += (k ? " " : "") + formatNumber(v[k]);
  return s + ")";
}

// Closest candidate by edit distance (case-insensitive), or "" if none is close.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// A token as echoed in a message: at most kEchoedChars characters of it, a longer one
// cut with "... (N characters)". Every message quoting user text goes through this.
constexpr std::size_t kEchoedChars = 80;
std::string echoed(const std::string& token);

// Parse a unit such as "cm", "g/cm^3", "cm/s^2", "kPa": SI factor and dimension.
// Throws InputError (message without location) for an unknown unit.
struct Unit { double factor = 1; Dimension dim; };
Unit parseUnit(const std::string& text);

}  // namespace shizuku
