// Declared dictionary parameters: each keyword is declared once, with its type,
// default (or required), allowed range, one-line meaning and old spellings, and
// read through that declaration. The declaration is the one source for
//   - reading and checking the value (errors name file:line:column and keyword),
//   - the defaults and ranges in the generated keyword tables (shizuku -keywords),
//   - the parameters in effect printed by -dryRun and the log.
//
// Declarations are grouped by dictionary scope ("system/controlDict",
// "system/sphSchemes: freeSurface", ...). A ParameterGroup registers itself in
// the global catalogue when constructed, so a group declared at namespace scope
// in the .cpp of its reader is listed by the table generator with no further
// wiring. That .cpp must be one the solver links from its static library (one
// holding a function the solver calls): a file nothing references is left out
// of the link, and its group out of the tables. Put the handles in a nested
// namespace (key::deltaT) so they do not clash with the members they fill.
//
// Ranges. Every number must be finite. A scalar may have a min and a max, each
// inclusive or exclusive. Beyond that every scalar with a physical dimension has
// a "physically sane" magnitude bound, |value| <= 1e12 in SI (lengths, times,
// velocities, accelerations, viscosities, densities, pressures, rates), unless
// the declaration sets another with sane(); dimensionless numbers and integers
// have none beyond their min/max. The bound catches unit slips and typos
// (nu 1e300) without constraining any real case. A quantity that cannot be tiny
// (a density: p ~ rho g H underflows) declares a lower one with saneMin().
//
// Usage (namespace scope in the reader's .cpp):
//   const ParameterGroup controlDict("system/controlDict", "run control");
//   const ScalarParameter deltaT =
//       controlDict.scalar("deltaT", dim::time, "time step (initial step with adjustTimeStep)")
//           .required().min(1e-12);
//   ... rc.deltaT = deltaT.read(dict);
#pragma once
#include "core/Dictionary.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

enum class ParameterType { scalar, integer, onOff, option, wordList, vector, vectorList };

// What a declaration holds. Numbers are SI.
struct ParameterInfo {
  std::string keyword;
  ParameterType type = ParameterType::scalar;
  Dimension dimension;                    // scalar and vector
  std::string doc;                        // one line
  bool required = false;
  double defaultNumber = 0;               // scalar, integer
  bool defaultSwitch = false;             // onOff
  std::string defaultWord;                // option
  std::string shownDefault;               // overrides the default's text (e.g. "endTime", "unlimited")
  double min = -1e308, max = 1e308;
  bool hasMin = false, hasMax = false;
  bool minInclusive = true, maxInclusive = true;
  double sane = 0;                        // |value| <= sane when > 0
  double saneLow = 0;                     // a nonzero |value| >= saneLow when > 0
  std::vector<std::string> options;       // option
  std::vector<std::string> oldNames;      // earlier spellings, still read with a warning
  std::string scope;                      // set by the group

  std::string unit() const;               // "m/s", "s", "" (dimensionless)
  std::string defaultText() const;        // "0.2", "1e-8 s", "AMG", "on", "required"
  std::string rangeText() const;          // "[1e-12, 1e12] s", "> 0", "AMG, ILU0, ..."
  std::string typeText() const;           // "scalar", "integer", "switch", "word", ...
};

// One dictionary scope: its parameters in declaration order.
struct ParameterScope {
  std::string scope, doc;
  std::vector<std::unique_ptr<ParameterInfo>> parameters;
};

// Every declared scope, in registration order (the generator sorts by name).
std::vector<std::shared_ptr<ParameterScope>>& parameterCatalogue();

// One value read (or defaulted), for -dryRun and the log.
struct ParameterValue {
  std::string scope, dictionary, keyword, value;  // value with unit, e.g. "0.001 s"
  bool defaulted = false;
  bool computed = false;  // a default the reader computed (depends on other values)
};
// The values read so far, each (dictionary, keyword) once, latest value kept.
std::vector<ParameterValue>& parametersInEffect();
// "  scope: keyword = value unit (default)" lines, grouped by scope.
std::string describeParametersInEffect();

// Keyword tables (Markdown) generated from the catalogue: the scopes in sorted
// order, one table (keyword, default, range, meaning) per scope.
std::vector<std::string> parameterScopes();
std::string keywordTableMarkdown(const std::string& scope);  // "" for an unknown scope
std::string keywordTablesMarkdown();                         // every scope, each under a heading

// The keyword under which `info` is written in `d` (itself or an old spelling,
// with a warning), or "" when absent. Marks what it looks at as read.
std::string presentKeyword(const ParameterInfo& info, const Dictionary& d);
// Record a value read or defaulted.
void recordParameter(const ParameterInfo& info, const Dictionary* d, const std::string& value, bool defaulted,
                     bool computed = false);
// Range checks; `key` is the keyword as written.
void checkRange(const ParameterInfo& info, const Dictionary& d, const std::string& key, double value);

// Common part of the typed handles below: the fluent setters and the lookup of
// the keyword, or one of its old spellings, in a dictionary.
template <class Self>
class ParameterHandle {
 public:
  explicit ParameterHandle(ParameterInfo* info) : info_(info) {}
  Self& required() { info_->required = true; return self(); }
  Self& oldName(const std::string& name) { info_->oldNames.push_back(name); return self(); }
  Self& shownDefault(const std::string& text) { info_->shownDefault = text; return self(); }
  const ParameterInfo& info() const { return *info_; }
  const std::string& keyword() const { return info_->keyword; }

 protected:
  ParameterInfo* info_;
  Self& self() { return static_cast<Self&>(*this); }
  // An absent sub-dictionary (a null dictionary): the default, recorded for -dryRun.
  template <class T>
  T absent(T def) const {
    recordParameter(*info_, nullptr, info_->defaultText(), true);
    return def;
  }
};

class ScalarParameter : public ParameterHandle<ScalarParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  ScalarParameter& def(double v) { info_->defaultNumber = v; info_->required = false; return *this; }
  ScalarParameter& min(double v) { info_->min = v; info_->hasMin = true; info_->minInclusive = true; return *this; }
  ScalarParameter& above(double v) { min(v); info_->minInclusive = false; return *this; }
  ScalarParameter& max(double v) { info_->max = v; info_->hasMax = true; info_->maxInclusive = true; return *this; }
  ScalarParameter& below(double v) { max(v); info_->maxInclusive = false; return *this; }
  ScalarParameter& sane(double magnitude) { info_->sane = magnitude; return *this; }
  // A lower sane magnitude, for a quantity whose smallness makes derived values underflow.
  ScalarParameter& saneMin(double magnitude) { info_->saneLow = magnitude; return *this; }
  // The value in `d`, or the default when absent (a required keyword missing is an error).
  double read(const Dictionary& d) const;
  // A null dictionary (an absent sub-dictionary) gives the default.
  double read(const Dictionary* d) const { return d ? read(*d) : absent(info_->defaultNumber); }
  // With a default the caller computes from other values (declare shownDefault()
  // to document it); -dryRun marks it "(default, computed)".
  double readOr(const Dictionary& d, double def) const;
  // The same for an absent sub-dictionary (nullptr).
  double readOr(const Dictionary* d, double def) const;
  // With another dimension than declared (a keyword whose unit depends on a mode).
  double readOr(const Dictionary& d, double def, Dimension dimension) const;
};

class IntParameter : public ParameterHandle<IntParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  IntParameter& def(int v) { info_->defaultNumber = v; info_->required = false; return *this; }
  IntParameter& min(int v) { info_->min = v; info_->hasMin = true; return *this; }
  IntParameter& max(int v) { info_->max = v; info_->hasMax = true; return *this; }
  int read(const Dictionary& d) const;
  int read(const Dictionary* d) const { return d ? read(*d) : absent(int(info_->defaultNumber)); }
};

class SwitchParameter : public ParameterHandle<SwitchParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  SwitchParameter& def(bool v) { info_->defaultSwitch = v; info_->required = false; return *this; }
  bool read(const Dictionary& d) const;
  bool read(const Dictionary* d) const { return d ? read(*d) : absent(info_->defaultSwitch); }
};

// A word from a fixed list; a wrong word is an error with "did you mean".
class OptionParameter : public ParameterHandle<OptionParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  OptionParameter& def(const std::string& v) { info_->defaultWord = v; info_->required = false; return *this; }
  std::string read(const Dictionary& d) const;
  std::string read(const Dictionary* d) const { return d ? read(*d) : absent(info_->defaultWord); }
};

class WordListParameter : public ParameterHandle<WordListParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  WordListParameter& def(const std::string& shown) { info_->shownDefault = shown; info_->required = false; return *this; }
  std::vector<std::string> read(const Dictionary& d) const;  // absent: empty
};

class VectorParameter : public ParameterHandle<VectorParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  VectorParameter& sane(double magnitude) { info_->sane = magnitude; return *this; }
  // Optional, the zero vector when absent (shown as `shown`, e.g. "0 (the origin)").
  VectorParameter& defZero(const std::string& shown) { info_->shownDefault = shown; info_->required = false; return *this; }
  template <int D> Vec<D> read(const Dictionary& d) const;
};

// A list of vectors ((x y) (x y) ...), each component range-checked.
class VectorListParameter : public ParameterHandle<VectorListParameter> {
 public:
  using ParameterHandle::ParameterHandle;
  template <int D> std::vector<Vec<D>> read(const Dictionary& d) const;  // required
};

// A dictionary scope; registered in parameterCatalogue() on construction.
class ParameterGroup {
 public:
  ParameterGroup(const std::string& scope, const std::string& doc);
  ScalarParameter scalar(const std::string& keyword, Dimension d, const std::string& doc) const;
  IntParameter integer(const std::string& keyword, const std::string& doc) const;
  SwitchParameter onOff(const std::string& keyword, const std::string& doc) const;
  OptionParameter option(const std::string& keyword, const std::vector<std::string>& options,
                         const std::string& doc) const;
  WordListParameter wordList(const std::string& keyword, const std::string& doc) const;
  VectorParameter vector(const std::string& keyword, Dimension d, const std::string& doc) const;
  VectorListParameter vectorList(const std::string& keyword, Dimension d, const std::string& doc) const;
  const std::string& scope() const { return data_->scope; }

 private:
  std::shared_ptr<ParameterScope> data_;
  ParameterInfo* add(const std::string& keyword, ParameterType type, const std::string& doc) const;
};

}  // namespace shizuku
