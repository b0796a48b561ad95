// The catalogue of declared parameters (Parameter.hpp): groups registering
// their scope, the text of a declaration's unit, default and range for the
// keyword tables, and the list of values in effect for -dryRun and the log.
#include "core/Parameter.hpp"
#include <cmath>
#include <map>
#include <sstream>

namespace shizuku {

// --- declaration texts -------------------------------------------------------------

std::string ParameterInfo::unit() const {
  if (type != ParameterType::scalar && type != ParameterType::vector && type != ParameterType::vectorList) return "";
  if (dimension == dim::none) return "";
  const std::string s = dimension.str();  // "[m/s]"
  return s.size() > 2 && s.front() == '[' ? s.substr(1, s.size() - 2) : s;
}

std::string ParameterInfo::defaultText() const {
  if (!shownDefault.empty()) return shownDefault;
  if (required) return "required";
  switch (type) {
    case ParameterType::scalar: {
      const std::string u = unit();
      return formatNumber(defaultNumber) + (u.empty() ? "" : " " + u);
    }
    case ParameterType::integer: return formatNumber(defaultNumber);
    case ParameterType::onOff: return defaultSwitch ? "on" : "off";
    case ParameterType::option: return defaultWord;
    case ParameterType::wordList: return "()";
    case ParameterType::vector:
    case ParameterType::vectorList: return "required";
  }
  return "";
}

std::string ParameterInfo::typeText() const {
  switch (type) {
    case ParameterType::scalar: return "scalar";
    case ParameterType::integer: return "integer";
    case ParameterType::onOff: return "switch";
    case ParameterType::option: return "word";
    case ParameterType::wordList: return "word list";
    case ParameterType::vector: return "vector";
    case ParameterType::vectorList: return "vector list";
  }
  return "";
}

std::string ParameterInfo::rangeText() const {
  if (type == ParameterType::option) {
    std::string s;
    for (const auto& o : options) s += (s.empty() ? "" : " \\| ") + o;
    return s;
  }
  if (type == ParameterType::onOff) return "on \\| off";
  if (type != ParameterType::scalar && type != ParameterType::integer && type != ParameterType::vector &&
      type != ParameterType::vectorList)
    return "";
  const bool lowSet = hasMin || sane > 0, highSet = hasMax || sane > 0;
  const double lo = hasMin ? (sane > 0 ? std::max(min, -sane) : min) : -sane;
  const double hi = hasMax ? (sane > 0 ? std::min(max, sane) : max) : sane;
  const bool loIn = hasMin && lo == min ? minInclusive : true;
  const bool hiIn = hasMax && hi == max ? maxInclusive : true;
  const std::string u = unit().empty() ? "" : " " + unit();
  std::string s;
  if (lowSet && highSet) {
    s = std::string(loIn ? "[" : "(") + formatNumber(lo) + ", " + formatNumber(hi) + (hiIn ? "]" : ")");
  } else if (lowSet) {
    s = std::string(loIn ? ">= " : "> ") + formatNumber(lo);
  } else if (highSet) {
    s = std::string(hiIn ? "<= " : "< ") + formatNumber(hi);
  } else {
    return type == ParameterType::integer ? "any integer" : "any finite";
  }
  if (saneLow > 0) s += ", not below " + formatNumber(saneLow);
  return s + u;
}

// --- groups --------------------------------------------------------------------------

std::vector<std::shared_ptr<ParameterScope>>& parameterCatalogue() {
  static std::vector<std::shared_ptr<ParameterScope>> groups;
  return groups;
}

ParameterGroup::ParameterGroup(const std::string& scope, const std::string& doc)
    : data_(std::make_shared<ParameterScope>()) {
  data_->scope = scope;
  data_->doc = doc;
  parameterCatalogue().push_back(data_);
}

ParameterInfo* ParameterGroup::add(const std::string& keyword, ParameterType type, const std::string& doc) const {
  auto info = std::make_unique<ParameterInfo>();
  info->keyword = keyword;
  info->type = type;
  info->doc = doc;
  info->scope = data_->scope;
  info->required = true;  // until a default is declared
  data_->parameters.push_back(std::move(info));
  return data_->parameters.back().get();
}

namespace {
// Dimensions with a physical unit get the sane magnitude bound |x| <= 1e12 (SI).
constexpr double kSaneMagnitude = 1e12;
}  // namespace

ScalarParameter ParameterGroup::scalar(const std::string& keyword, Dimension d, const std::string& doc) const {
  ParameterInfo* p = add(keyword, ParameterType::scalar, doc);
  p->dimension = d;
  if (d != dim::none) p->sane = kSaneMagnitude;
  return ScalarParameter(p);
}

IntParameter ParameterGroup::integer(const std::string& keyword, const std::string& doc) const {
  return IntParameter(add(keyword, ParameterType::integer, doc));
}

SwitchParameter ParameterGroup::onOff(const std::string& keyword, const std::string& doc) const {
  return SwitchParameter(add(keyword, ParameterType::onOff, doc));
}

OptionParameter ParameterGroup::option(const std::string& keyword, const std::vector<std::string>& options,
                                       const std::string& doc) const {
  ParameterInfo* p = add(keyword, ParameterType::option, doc);
  p->options = options;
  return OptionParameter(p);
}

WordListParameter ParameterGroup::wordList(const std::string& keyword, const std::string& doc) const {
  return WordListParameter(add(keyword, ParameterType::wordList, doc));
}

VectorParameter ParameterGroup::vector(const std::string& keyword, Dimension d, const std::string& doc) const {
  ParameterInfo* p = add(keyword, ParameterType::vector, doc);
  p->dimension = d;
  if (d != dim::none) p->sane = kSaneMagnitude;
  return VectorParameter(p);
}

VectorListParameter ParameterGroup::vectorList(const std::string& keyword, Dimension d, const std::string& doc) const {
  ParameterInfo* p = add(keyword, ParameterType::vectorList, doc);
  p->dimension = d;
  if (d != dim::none) p->sane = kSaneMagnitude;
  return VectorListParameter(p);
}

// --- values in effect ------------------------------------------------------------------

std::vector<ParameterValue>& parametersInEffect() {
  static std::vector<ParameterValue> values;
  return values;
}

void recordParameter(const ParameterInfo& info, const Dictionary* d, const std::string& value, bool defaulted,
                     bool computed) {
  ParameterValue v{info.scope, d ? d->name() : info.scope, info.keyword, value, defaulted, computed};
  for (auto& old : parametersInEffect())
    if (old.dictionary == v.dictionary && old.keyword == v.keyword) {
      old = v;
      return;
    }
  parametersInEffect().push_back(v);
}

std::string describeParametersInEffect() {
  // Group by dictionary and scope (a function object's dictionary holds keys of two
  // scopes) in first-read order; a dictionary path is shown from system/ or constant/ on.
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, std::vector<const ParameterValue*>> groups;
  for (const auto& v : parametersInEffect()) {
    const auto key = std::make_pair(v.dictionary, v.scope);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&v);
  }
  std::ostringstream os;
  os << "Parameters in effect ((default): not written in the case):\n";
  for (const auto& key : order) {
    std::string shown = key.first;
    for (const char* root : {"system/", "constant/"}) {
      const auto k = shown.rfind(root);
      if (k != std::string::npos) { shown = shown.substr(k); break; }
    }
    os << "  [" << key.second << "]" << (shown == key.second ? "" : " " + shown) << "\n";
    for (const auto* v : groups[key])
      os << "    " << v->keyword << " = " << v->value
         << (v->computed ? " (default, computed)" : v->defaulted ? " (default)" : "") << "\n";
  }
  return os.str();
}

}  // namespace shizuku
