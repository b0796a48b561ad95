// Markdown keyword tables from the parameter catalogue (Parameter.hpp): one
// table per dictionary scope with keyword, default (with unit), allowed range
// and meaning. etc/update-keyword-tables writes them into README.md and
// docs/dictionaries.md; a unit test checks those copies are current.
#include "core/Parameter.hpp"
#include <algorithm>
#include <sstream>

namespace shizuku {

namespace {

// A table cell: '|' would end the cell.
std::string cell(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '|' && (i == 0 || s[i - 1] != '\\')) out += '\\';
    out += s[i];
  }
  return out;
}

}  // namespace

std::vector<std::string> parameterScopes() {
  std::vector<std::string> scopes;
  for (const auto& g : parameterCatalogue())
    if (std::find(scopes.begin(), scopes.end(), g->scope) == scopes.end()) scopes.push_back(g->scope);
  std::sort(scopes.begin(), scopes.end());
  return scopes;
}

std::string keywordTableMarkdown(const std::string& scope) {
  std::ostringstream os;
  bool any = false;
  // Groups of one scope declared in several files: in order of their first keyword.
  std::vector<const ParameterScope*> groups;
  for (const auto& g : parameterCatalogue())
    if (g->scope == scope && !g->parameters.empty()) groups.push_back(g.get());
  std::sort(groups.begin(), groups.end(), [](const ParameterScope* a, const ParameterScope* b) {
    return a->parameters.front()->keyword < b->parameters.front()->keyword;
  });
  for (const auto* g : groups)
    for (const auto& p : g->parameters) {
      if (!any) os << "| keyword | default | range | meaning |\n|---|---|---|---|\n";
      any = true;
      std::string meaning = p->doc;
      for (const auto& old : p->oldNames) meaning += " (old spelling `" + old + "` still read)";
      os << "| `" << p->keyword << "` | " << cell(p->defaultText()) << " | " << cell(p->rangeText()) << " | "
         << cell(meaning) << " |\n";
    }
  return os.str();
}

std::string keywordTablesMarkdown() {
  std::ostringstream os;
  bool first = true;
  for (const auto& scope : parameterScopes()) {
    std::string doc;
    for (const auto& g : parameterCatalogue())
      if (g->scope == scope && doc.empty()) doc = g->doc;
    os << (first ? "" : "\n") << "#### " << scope << "\n\n" << (doc.empty() ? "" : doc + "\n\n")
       << keywordTableMarkdown(scope);
    first = false;
  }
  return os.str();
}

}  // namespace shizuku
