// Lookups in a parsed case dictionary (docs/design.md 1.2): typed getters with
// unit/dimension checks, defaults recorded once for the log, "did you mean"
// errors for options and switches, and checkAllRead(), which turns every
// keyword nobody looked up into an InputError naming file, line and the
// closest known keyword. Reads whatever keys its callers ask for.
#include "core/Dictionary.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace shizuku {

namespace {

std::string describeValue(const DictValue& v) {
  switch (v.kind) {
    case DictValue::Kind::word: return "the word '" + echoed(v.text) + "'";
    case DictValue::Kind::string: return "the string \"" + echoed(v.text) + "\"";
    case DictValue::Kind::number: return "the number " + echoed(v.text);
    case DictValue::Kind::list: return "a list of " + std::to_string(v.items.size()) + " items";
    case DictValue::Kind::dict: return "a sub-dictionary";
  }
  return "?";
}

std::string components(int D) { return D == 1 ? "(x)" : D == 2 ? "(x y)" : "(x y z)"; }

std::string withUnit(const std::string& value, Dimension d) {
  return d == dim::none ? value : value + " " + d.str();
}

const std::vector<std::string> kSwitchTrue = {"on", "yes", "true"};
const std::vector<std::string> kSwitchFalse = {"off", "no", "false"};

}  // namespace

// --- basic access ------------------------------------------------------------

const DictValue* Dictionary::find(const std::string& key) const {
  queried_.insert(key);
  auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

const DictValue& Dictionary::require(const std::string& key, const std::string& expected) const {
  const DictValue* v = find(key);
  if (!v) {
    std::string m = "missing in dictionary '" + name_ + "'" + (expected.empty() ? "" : " (expected " + expected + ")");
    std::vector<std::string> unread;  // a present keyword nobody asked for may be this one misspelt
    for (const auto& k : order_)
      if (!queried_.count(k)) unread.push_back(k);
    const std::string near = closestMatch(key, unread);
    if (!near.empty())
      m += "; '" + near + "' (line " + std::to_string(location(near).line) + ") looks like a misspelling of it";
    error(key, m);
  }
  return *v;
}

bool Dictionary::found(const std::string& key) const { return find(key) != nullptr; }

bool Dictionary::isDict(const std::string& key) const {
  const DictValue* v = find(key);
  return v && v->kind == DictValue::Kind::dict;
}

const Dictionary& Dictionary::subDict(const std::string& key) const {
  const DictValue& v = require(key, "a sub-dictionary { ... }");
  if (v.kind != DictValue::Kind::dict) error(key, "expected a sub-dictionary { ... }, found " + describeValue(v));
  return *v.dict;
}

const Dictionary* Dictionary::subDictPtr(const std::string& key) const {
  const DictValue* v = find(key);
  if (!v) return nullptr;
  if (v->kind != DictValue::Kind::dict) error(key, "expected a sub-dictionary { ... }, found " + describeValue(*v));
  return v->dict.get();
}

std::vector<std::string> Dictionary::keys() const { return order_; }

const DictValue& Dictionary::value(const std::string& key) const { return require(key, ""); }

SourceLocation Dictionary::location(const std::string& key) const {
  auto it = keyLocation_.find(key);
  return it == keyLocation_.end() ? where_ : it->second;
}

void Dictionary::error(const std::string& key, const std::string& message) const {
  throw InputError(location(key).str() + ": keyword '" + echoed(key) + "': " + message);
}

void Dictionary::markRead(const std::string& key) const { queried_.insert(key); }

// --- numbers -------------------------------------------------------------------

double Dictionary::numberOf(const std::string& key, const DictValue& v, Dimension d) const {
  if (v.kind != DictValue::Kind::number) error(key, "expected " + d.describe() + ", found " + describeValue(v));
  if (v.hasUnit && v.unitDim != d)
    error(key, "unit [" + v.unitText + "] has dimension " + v.unitDim.str() + " but " + d.describe() + " is expected");
  return v.number;
}

double Dictionary::getScalar(const std::string& key, Dimension d) const {
  return numberOf(key, require(key, d.describe()), d);
}

double Dictionary::getScalarOr(const std::string& key, double def, Dimension d) const {
  if (const DictValue* v = find(key)) return numberOf(key, *v, d);
  recordDefault(key, withUnit(formatNumber(def), d));
  return def;
}

int Dictionary::getInt(const std::string& key) const {
  const DictValue& v = require(key, "an integer");
  const double x = numberOf(key, v, dim::none);
  if (x != std::floor(x) || std::abs(x) > 2147483647.0) error(key, "expected an integer, found " + echoed(v.text));
  return int(x);
}

int Dictionary::getIntOr(const std::string& key, int def) const {
  if (!found(key)) {
    recordDefault(key, std::to_string(def));
    return def;
  }
  return getInt(key);
}

std::vector<double> Dictionary::getScalarList(const std::string& key, Dimension d) const {
  const DictValue& v = require(key, "a list of numbers");
  if (v.kind == DictValue::Kind::number) return {numberOf(key, v, d)};
  if (v.kind != DictValue::Kind::list) error(key, "expected a list of numbers ( ... ), found " + describeValue(v));
  std::vector<double> out;
  for (const auto& item : v.items) out.push_back(numberOf(key, item, d));
  return out;
}

// --- vectors and matrices --------------------------------------------------------

template <int D>
Vec<D> Dictionary::vectorOf(const std::string& key, const DictValue& v, Dimension d) const {
  if (v.kind != DictValue::Kind::list)
    error(key, "expected a vector of " + std::to_string(D) + " components " + components(D) + ", found " +
               describeValue(v));
  if (int(v.items.size()) != D)
    error(key, "expected a vector of " + std::to_string(D) + " components " + components(D) + ", found " +
               std::to_string(v.items.size()) + " components");
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = numberOf(key, v.items[k], d);
  return x;
}

template <int D> Vec<D> Dictionary::getVector(const std::string& key, Dimension d) const {
  return vectorOf<D>(key, require(key, "a vector " + components(D)), d);
}

template <int D>
Vec<D> Dictionary::getVectorOr(const std::string& key, const Vec<D>& def, Dimension d) const {
  if (const DictValue* v = find(key)) return vectorOf<D>(key, *v, d);
  recordDefault(key, withUnit(formatNumber<D>(def), d));
  return def;
}

template <int D>
std::vector<Vec<D>> Dictionary::getVectorList(const std::string& key, Dimension d) const {
  const DictValue& v = require(key, "a list of vectors ((..) (..))");
  if (v.kind != DictValue::Kind::list)
    error(key, "expected a list of vectors ((..) (..)), found " + describeValue(v));
  std::vector<Vec<D>> out;
  for (const auto& item : v.items) out.push_back(vectorOf<D>(key, item, d));
  return out;
}

template <int D> Mat<D> Dictionary::getMatrix(const std::string& key, Dimension d) const {
  const DictValue& v = require(key, "a matrix written row by row");
  const std::string shape = std::to_string(D) + " x " + std::to_string(D);
  if (v.kind != DictValue::Kind::list || int(v.items.size()) != D)
    error(key, "expected a " + shape + " matrix written row by row, e.g. " +
               (D == 2 ? "((a b) (c d))" : "((a b c) (d e f) (g h i))") + ", found " +
               (v.kind == DictValue::Kind::list ? std::to_string(v.items.size()) + " rows" : describeValue(v)));
  Mat<D> m;
  for (int r = 0; r < D; ++r) {
    const DictValue& row = v.items[r];
    if (row.kind != DictValue::Kind::list || int(row.items.size()) != D)
      error(key, "expected a " + shape + " matrix: row " + std::to_string(r + 1) + " must have " +
                 std::to_string(D) + " numbers, found " +
                 (row.kind == DictValue::Kind::list ? std::to_string(row.items.size()) : describeValue(row)));
    for (int c = 0; c < D; ++c) m(r, c) = numberOf(key, row.items[c], d);
  }
  return m;
}

// --- words, options, switches -------------------------------------------------

std::string Dictionary::getWord(const std::string& key) const {
  const DictValue& v = require(key, "a word");
  if (v.kind != DictValue::Kind::word && v.kind != DictValue::Kind::string)
    error(key, "expected a word, found " + describeValue(v));
  return v.text;
}

std::string Dictionary::getWordOr(const std::string& key, const std::string& def) const {
  if (!found(key)) {
    recordDefault(key, def);
    return def;
  }
  return getWord(key);
}

std::string Dictionary::getOption(const std::string& key, const std::vector<std::string>& options) const {
  std::string list;
  for (const auto& o : options) list += (list.empty() ? "" : " | ") + o;
  const DictValue& v = require(key, "one of: " + list);
  if (v.kind != DictValue::Kind::word && v.kind != DictValue::Kind::string)
    error(key, "expected one of: " + list + "; found " + describeValue(v));
  if (std::find(options.begin(), options.end(), v.text) != options.end()) return v.text;
  const std::string near = closestMatch(v.text, options);
  error(key, "'" + echoed(v.text) + "' is not one of: " + list + (near.empty() ? "" : "; did you mean '" + near + "'?"));
}

std::string Dictionary::getOptionOr(const std::string& key, const std::vector<std::string>& options,
                                    const std::string& def) const {
  if (!found(key)) {
    recordDefault(key, def);
    return def;
  }
  return getOption(key, options);
}

bool Dictionary::getSwitch(const std::string& key) const {
  const DictValue& v = require(key, "a switch (on | off | yes | no | true | false)");
  if (v.kind == DictValue::Kind::word) {
    if (std::find(kSwitchTrue.begin(), kSwitchTrue.end(), v.text) != kSwitchTrue.end()) return true;
    if (std::find(kSwitchFalse.begin(), kSwitchFalse.end(), v.text) != kSwitchFalse.end()) return false;
  }
  std::vector<std::string> all = kSwitchTrue;
  all.insert(all.end(), kSwitchFalse.begin(), kSwitchFalse.end());
  const std::string near = v.kind == DictValue::Kind::word ? closestMatch(v.text, all) : "";
  error(key, "expected a switch (on | off | yes | no | true | false), found " + describeValue(v) +
             (near.empty() ? "" : "; did you mean '" + near + "'?"));
}

bool Dictionary::getSwitchOr(const std::string& key, bool def) const {
  if (!found(key)) {
    recordDefault(key, def ? "on" : "off");
    return def;
  }
  return getSwitch(key);
}

std::vector<std::string> Dictionary::getWordList(const std::string& key) const {
  const DictValue& v = require(key, "a list of words (a b c)");
  if (v.kind == DictValue::Kind::word || v.kind == DictValue::Kind::string) return {v.text};
  if (v.kind != DictValue::Kind::list) error(key, "expected a list of words (a b c), found " + describeValue(v));
  std::vector<std::string> out;
  for (const auto& item : v.items) {
    if (item.kind != DictValue::Kind::word && item.kind != DictValue::Kind::string)
      error(key, "expected a list of words (a b c), but item " + std::to_string(out.size() + 1) + " is " +
                 describeValue(item));
    out.push_back(item.text);
  }
  return out;
}

// --- read tracking --------------------------------------------------------------

void Dictionary::markAllRead() const {
  for (const auto& key : order_) {
    queried_.insert(key);
    const DictValue& v = entries_.at(key);
    if (v.kind == DictValue::Kind::dict) v.dict->markAllRead();
  }
}

void Dictionary::checkAllRead() const {
  for (const auto& key : order_) {
    if (!queried_.count(key)) {
      std::vector<std::string> known(queried_.begin(), queried_.end());
      std::string m = location(key).str() + ": unknown keyword '" + echoed(key) + "'";
      const std::string near = closestMatch(key, known);
      if (!near.empty()) {
        m += "; did you mean '" + near + "'?";
      } else if (!known.empty()) {
        m += " (keywords read here:";
        for (const auto& k : known) m += " " + k;
        m += ")";
      }
      throw InputError(m);
    }
    const DictValue& v = entries_.at(key);
    if (v.kind == DictValue::Kind::dict) v.dict->checkAllRead();
  }
}

std::vector<std::string>& Dictionary::defaultsUsed() {
  static std::vector<std::string> lines;
  return lines;
}

void Dictionary::recordDefault(const std::string& key, const std::string& value) const {
  const std::string prefix = name_ + ": " + key + " default ";
  auto& lines = defaultsUsed();
  for (const auto& l : lines)
    if (l.compare(0, prefix.size(), prefix) == 0) return;
  lines.push_back(prefix + value);
}

// --- explicit instantiations -------------------------------------------------------

#define SHIZUKU_DICTIONARY_INSTANTIATE(D)                                                          \
  template Vec<D> Dictionary::vectorOf<D>(const std::string&, const DictValue&, Dimension) const;   \
  template Vec<D> Dictionary::getVector<D>(const std::string&, Dimension) const;                   \
  template Vec<D> Dictionary::getVectorOr<D>(const std::string&, const Vec<D>&, Dimension) const;  \
  template std::vector<Vec<D>> Dictionary::getVectorList<D>(const std::string&, Dimension) const;  \
  template Mat<D> Dictionary::getMatrix<D>(const std::string&, Dimension) const;
SHIZUKU_DICTIONARY_INSTANTIATE(1)
SHIZUKU_DICTIONARY_INSTANTIATE(2)
SHIZUKU_DICTIONARY_INSTANTIATE(3)
#undef SHIZUKU_DICTIONARY_INSTANTIATE

}  // namespace shizuku
