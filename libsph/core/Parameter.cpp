// Reading a declared parameter (Parameter.hpp): find the keyword or an old
// spelling, read it through the Dictionary getters (type, unit and dimension
// checks, did-you-mean for options), check the declared range, and record the
// value in effect. Absent keywords take the declared default, which the
// Dictionary also records for the log's "default:" lines.
#include "core/Parameter.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <cmath>
#include <set>

namespace shizuku {

namespace {

bool written(const Dictionary& d, const std::string& key) {
  const auto keys = d.keys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string withUnit(const std::string& value, const ParameterInfo& info) {
  const std::string u = info.unit();
  return u.empty() ? value : value + " " + u;
}

// The value as the user wrote it (with the SI value when a unit was written).
std::string asWritten(const ParameterInfo& info, const Dictionary& d, const std::string& key, double value) {
  const DictValue& v = d.value(key);
  if (v.kind != DictValue::Kind::number) return withUnit(formatNumber(value), info);
  if (!v.hasUnit) return echoed(v.text);
  return echoed(v.text) + " [" + v.unitText + "] (" + withUnit(formatNumber(value), info) + ")";
}

}  // namespace

std::string presentKeyword(const ParameterInfo& info, const Dictionary& d) {
  if (d.found(info.keyword)) {
    for (const auto& old : info.oldNames)
      if (written(d, old))
        d.error(old, "is the old spelling of '" + info.keyword + "', which is also given; remove '" + old + "'");
    return info.keyword;
  }
  for (const auto& old : info.oldNames)
    if (written(d, old)) {
      static std::set<std::string> warned;  // the controlDict is re-read while running: warn once
      const std::string where = d.location(old).str();
      if (warned.insert(where + old).second)
        Log::get().warning(where + ": keyword '" + old + "' is an old spelling; write '" + info.keyword +
                           "' (read as '" + info.keyword + "')");
      d.markRead(old);
      return old;
    }
  return "";
}

void checkRange(const ParameterInfo& info, const Dictionary& d, const std::string& key, double value) {
  auto fail = [&](const std::string& what, double bound) {
    d.error(key, asWritten(info, d, key, value) + " " + what + " " + withUnit(formatNumber(bound), info));
  };
  if (!std::isfinite(value)) d.error(key, asWritten(info, d, key, value) + " is not a finite number");
  if (info.hasMin && info.minInclusive && value < info.min) fail("is below the smallest allowed", info.min);
  if (info.hasMin && !info.minInclusive && !(value > info.min)) fail("must be greater than", info.min);
  if (info.hasMax && info.maxInclusive && value > info.max) fail("is above the largest allowed", info.max);
  if (info.hasMax && !info.maxInclusive && !(value < info.max)) fail("must be less than", info.max);
  if (info.sane > 0 && std::abs(value) > info.sane)
    fail("is beyond the physically sane magnitude", info.sane);
  if (info.saneLow > 0 && value != 0 && std::abs(value) < info.saneLow)
    fail("is below the physically sane magnitude", info.saneLow);
}

// --- scalars -------------------------------------------------------------------

namespace {

double readScalar(const ParameterInfo& info, const Dictionary& d, double def, Dimension dm, bool computed) {
  const std::string key = presentKeyword(info, d);
  if (key.empty()) {
    if (info.required) return d.getScalar(info.keyword, dm);  // throws: missing, with a misspelling hint
    d.getScalarOr(info.keyword, def, dm);
    recordParameter(info, &d, computed ? withUnit(formatNumber(def), info) : info.defaultText(), true, computed);
    return def;
  }
  const double v = d.getScalar(key, dm);
  checkRange(info, d, key, v);
  recordParameter(info, &d, withUnit(formatNumber(v), info), false);
  return v;
}

}  // namespace

double ScalarParameter::read(const Dictionary& d) const {
  return readScalar(*info_, d, info_->defaultNumber, info_->dimension, false);
}

double ScalarParameter::readOr(const Dictionary& d, double def) const {
  return readScalar(*info_, d, def, info_->dimension, true);
}

double ScalarParameter::readOr(const Dictionary* d, double def) const {
  if (d) return readOr(*d, def);
  recordParameter(*info_, nullptr, withUnit(formatNumber(def), *info_), true, true);
  return def;
}

double ScalarParameter::readOr(const Dictionary& d, double def, Dimension dimension) const {
  ParameterInfo other = *info_;  // the unit shown follows the dimension used
  other.dimension = dimension;
  return readScalar(other, d, def, dimension, true);
}

// --- integers, switches, options, word lists -------------------------------------

int IntParameter::read(const Dictionary& d) const {
  const std::string key = presentKeyword(*info_, d);
  if (key.empty()) {
    if (info_->required) return d.getInt(info_->keyword);
    const int def = int(info_->defaultNumber);
    d.getIntOr(info_->keyword, def);
    recordParameter(*info_, &d, info_->defaultText(), true);
    return def;
  }
  const int v = d.getInt(key);
  checkRange(*info_, d, key, v);
  recordParameter(*info_, &d, std::to_string(v), false);
  return v;
}

bool SwitchParameter::read(const Dictionary& d) const {
  const std::string key = presentKeyword(*info_, d);
  if (key.empty()) {
    if (info_->required) return d.getSwitch(info_->keyword);
    d.getSwitchOr(info_->keyword, info_->defaultSwitch);
    recordParameter(*info_, &d, info_->defaultText(), true);
    return info_->defaultSwitch;
  }
  const bool v = d.getSwitch(key);
  recordParameter(*info_, &d, v ? "on" : "off", false);
  return v;
}

std::string OptionParameter::read(const Dictionary& d) const {
  const std::string key = presentKeyword(*info_, d);
  if (key.empty()) {
    if (info_->required) return d.getOption(info_->keyword, info_->options);
    d.getOptionOr(info_->keyword, info_->options, info_->defaultWord);
    recordParameter(*info_, &d, info_->defaultText(), true);
    return info_->defaultWord;
  }
  const std::string v = d.getOption(key, info_->options);
  recordParameter(*info_, &d, v, false);
  return v;
}

std::vector<std::string> WordListParameter::read(const Dictionary& d) const {
  const std::string key = presentKeyword(*info_, d);
  if (key.empty()) {
    if (info_->required) return d.getWordList(info_->keyword);
    recordParameter(*info_, &d, info_->defaultText(), true);
    return {};
  }
  const std::vector<std::string> v = d.getWordList(key);
  std::string text = "(";
  for (const auto& w : v) text += (text.size() > 1 ? " " : "") + w;
  recordParameter(*info_, &d, text + ")", false);
  return v;
}

// --- vectors ---------------------------------------------------------------------

template <int D> Vec<D> VectorParameter::read(const Dictionary& d) const {
  std::string key = presentKeyword(*info_, d);
  if (key.empty() && !info_->required) {
    const Vec<D> zero = d.getVectorOr<D>(info_->keyword, Vec<D>::Zero(), info_->dimension);
    recordParameter(*info_, &d, info_->defaultText(), true);
    return zero;
  }
  if (key.empty()) key = info_->keyword;  // required: getVector reports it missing
  const Vec<D> v = d.getVector<D>(key, info_->dimension);
  for (int k = 0; k < D; ++k) checkRange(*info_, d, key, v[k]);
  std::string text = "(";
  for (int k = 0; k < D; ++k) text += (k ? " " : "") + formatNumber(v[k]);
  recordParameter(*info_, &d, withUnit(text + ")", *info_), false);
  return v;
}

template <int D> std::vector<Vec<D>> VectorListParameter::read(const Dictionary& d) const {
  std::string key = presentKeyword(*info_, d);
  if (key.empty()) key = info_->keyword;
  const std::vector<Vec<D>> list = d.getVectorList<D>(key, info_->dimension);
  std::string text = "(";
  for (const auto& v : list) {
    for (int k = 0; k < D; ++k) checkRange(*info_, d, key, v[k]);
    text += std::string(text.size() > 1 ? " " : "") + "(";
    for (int k = 0; k < D; ++k) text += (k ? " " : "") + formatNumber(v[k]);
    text += ")";
  }
  recordParameter(*info_, &d, withUnit(text + ")", *info_), false);
  return list;
}

template std::vector<Vec<2>> VectorListParameter::read<2>(const Dictionary&) const;
template std::vector<Vec<3>> VectorListParameter::read<3>(const Dictionary&) const;
template Vec<1> VectorParameter::read<1>(const Dictionary&) const;
template Vec<2> VectorParameter::read<2>(const Dictionary&) const;
template Vec<3> VectorParameter::read<3>(const Dictionary&) const;

}  // namespace shizuku
