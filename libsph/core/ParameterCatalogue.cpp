// The catalogue of declared parameters (Parameter.hpp): groups registering
// their scope, the text of a declaration's unit, default and range for the
// keyword tables, and the list of values in effect for -dryRun and the log.
#include "core/Parameter.hpp"
#include <cmath>
#include <map>
#include <sstream>

namespace shizuku {

namespace {

// 1e-08 -> 1e-8, 1e+300 -> 1e300: the exponent as a user writes it.
std::string tidyExponent(std::string t) {
  const auto e = t.find('e');
  if (e == std::string::npos) return t;
  std::string mant = t.substr(0, e), exp = t.substr(e + 1), sign;
  if (!exp.empty() && (exp[0] == '+' || exp[0] == '-')) {
    if (exp[0] == '-') sign = "-";
    exp.erase(0, 1);
  }
  while (exp.size() > 1 && exp[0] == '0') exp.erase(0, 1);
  return mant + "e" + sign + exp;
}

}  // namespace

std::string formatNumber(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  std::string t = tidyExponent(s.str());
  // Round numbers far from 1 read better as 1e7 and 1e-4 than 10000000 and 0.0001.
  if ((std::abs(x) >= 1e5 || (x != 0 && std::abs(x) < 1e-3)) && t.find('e') == std::string::npos) {
    for (int digits = 1; digits <= 10; ++digits) {
      std::ostringstream e;
      e.precision(digits - 1);
      e << std::scientific << x;
      if (std::stod(e.str()) == x) {
        std::string sci = e.str();
        const auto k = sci.find('e');
        std::string mant = sci.substr(0, k);
        if (mant.find('.') != std::string::npos) {
          while (mant.back() == '0') mant.pop_back();
          if (mant.back() == '.') mant.pop_back();
        }
        sci = tidyExponent(mant + sci.substr(k));
        if (sci.size() < t.size()) t = sci;
        break;
      }
    }
  }
  return t;
}

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
