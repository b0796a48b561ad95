// Parser of case dictionaries (docs/design.md 1.2): turns the text of a file into
// a Dictionary tree. Handles the FoamFile header, // and /* */ comments,
// `keyword value(s);`, sub-dictionaries, nested lists, words, numbers,
// "strings", $macro and $sub/macro expansion, #include and #includeIfPresent,
// and units in square brackets after a number or a list (converted to SI).
// Every syntax error is an InputError "file:line:column: [keyword 'k': ]what
// was expected". Reads no dictionary keys itself.
#include "core/Dictionary.hpp"
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace shizuku {

namespace {

// A text file: no NUL byte, no control character other than white space,
// valid UTF-8. Anything else is reported as a binary file.
void checkText(const std::string& text, const std::string& fileNamed) {
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = text[i];
    if (c == '\n') { ++line; continue; }
    if (c == 0 || (c < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v') || c == 0x7f) {
      std::ostringstream m;
      m << fileNamed << " is not a text file (binary byte 0x" << std::hex << int(c)
        << std::dec << " at line " << line << ")";
      throw InputError(m.str());
    }
    if (c < 0x80) continue;
    int extra = (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xe ? 2 : (c >> 3) == 0x1e ? 3 : -1;
    bool ok = extra > 0 && c != 0xc0 && c != 0xc1 && c <= 0xf4;
    for (int k = 1; ok && k <= extra; ++k) ok = i + k < text.size() && (((unsigned char)text[i + k]) >> 6) == 0x2;
    if (!ok)
      throw InputError(fileNamed + " is not a text file (invalid UTF-8 at line " +
                       std::to_string(line) + ")");
    i += extra;
  }
}

bool readFile(const std::string& path, std::string& text) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  text = ss.str();
  return true;
}

bool isNumber(const std::string& s) {
  std::size_t i = 0, n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < n && std::isdigit((unsigned char)s[i])) ++i, ++digits;
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && std::isdigit((unsigned char)s[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t e = 0;
    while (i < n && std::isdigit((unsigned char)s[i])) ++i, ++e;
    if (e == 0) return false;
  }
  return i == n;
}

struct Token {
  enum Type { word, number, string, lbrace, rbrace, lparen, rparen, semicolon, unit, macro, directive, end };
  Type type = end;
  std::string text;
  double numberValue = 0;
  SourceLocation where;
  int endLine = 0, endColumn = 0;  // position just after the token
};

std::string describe(const Token& t) {
  switch (t.type) {
    case Token::end: return "the end of the file";
    case Token::string: return "\"" + echoed(t.text) + "\"";
    case Token::unit: return "[" + echoed(t.text) + "]";
    case Token::macro: return "$" + echoed(t.text);
    case Token::directive: return "#" + echoed(t.text);
    default: return "'" + echoed(t.text) + "'";
  }
}

class Lexer {
 public:
  Lexer(std::string text, std::string file, std::string includedFrom = "")
      : text_(std::move(text)), file_(std::move(file)), includedFrom_(std::move(includedFrom)) {
    if (text_.compare(0, 3, "\xef\xbb\xbf") == 0) pos_ = 3;  // a UTF-8 byte-order mark at the start is skipped
  }
  const std::string& file() const { return file_; }
  const Token& peek() {
    if (!hasPeek_) { peeked_ = lex(); hasPeek_ = true; }
    return peeked_;
  }
  Token next() {
    Token t = hasPeek_ ? std::move(peeked_) : lex();
    hasPeek_ = false;
    lastLine_ = t.endLine;
    lastColumn_ = t.endColumn;
    return t;
  }
  // Position just after the last token returned by next().
  SourceLocation lastEnd() const { return {file_, lastLine_, lastColumn_, includedFrom_}; }

 private:
  std::string text_, file_, includedFrom_;
  std::size_t pos_ = 0;
  int line_ = 1, column_ = 1, lastLine_ = 1, lastColumn_ = 1;
  bool hasPeek_ = false;
  Token peeked_;

  char at(std::size_t k = 0) const { return pos_ + k < text_.size() ? text_[pos_ + k] : '\0'; }
  bool done() const { return pos_ >= text_.size(); }
  void advance() {
    const unsigned char c = text_[pos_++];
    if (c == '\n') { ++line_; column_ = 1; }
    else if ((c & 0xc0) != 0x80) ++column_;
  }
  static bool delimiter(char c) {
    return std::isspace((unsigned char)c) || c == '{' || c == '}' || c == '(' || c == ')' ||
           c == ';' || c == '"' || c == '[' || c == ']' || c == '\0';
  }
  bool commentStart() const { return at() == '/' && (at(1) == '/' || at(1) == '*'); }

  void skipSpaceAndComments() {
    for (;;) {
      while (!done() && std::isspace((unsigned char)at())) advance();
      if (at() == '/' && at(1) == '/') {
        while (!done() && at() != '\n') advance();
      } else if (at() == '/' && at(1) == '*') {
        const int l = line_, c = column_;
        advance(); advance();
        while (!done() && !(at() == '*' && at(1) == '/')) advance();
        if (done()) throw InputError(SourceLocation{file_, l, c, includedFrom_}.str() + ": comment '/*' is never closed (missing '*/')");
        advance(); advance();
      } else {
        return;
      }
    }
  }

  std::string wordChars() {
    std::string s;
    while (!done() && !delimiter(at()) && !commentStart()) {
      if ((unsigned char)at() >= 0x80) nonAscii(s);
      s += at();
      advance();
    }
    return s;
  }

  // Keywords, numbers, units and macro names are ASCII; a non-ASCII character there (a
  // no-break space pasted from a web page, a typographic quote) is named with its code
  // point. Comments and "strings" may hold any UTF-8 (checkText has validated it).
  [[noreturn]] void nonAscii(const std::string& before) const {
    const unsigned char c = at();
    const int extra = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : 1;
    unsigned code = c & (0x3f >> extra);
    for (int k = 1; k <= extra; ++k) code = (code << 6) | ((unsigned char)at(k) & 0x3f);
    char hex[16];
    std::snprintf(hex, sizeof hex, "U+%04X", code);
    const std::string name = characterName(code);
    throw InputError(SourceLocation{file_, line_, column_, includedFrom_}.str() + ": non-ASCII character " + hex +
                     (name.empty() ? "" : " (" + name + ")") +
                     (before.empty() ? "" : " after '" + echoed(before) + "'") +
                     "; keywords, numbers and units must be plain ASCII (only comments and \"strings\" may hold "
                     "other characters)");
  }

  static std::string characterName(unsigned code) {
    switch (code) {
      case 0x00a0: return "no-break space";
      case 0x00b5: return "micro sign";
      case 0x2009: return "thin space";
      case 0x200b: return "zero-width space";
      case 0x2013: return "en dash";
      case 0x2018: case 0x2019: return "typographic single quote";
      case 0x201c: case 0x201d: return "typographic double quote";
      case 0x2212: return "minus sign; write the ASCII '-'";
      case 0x3000: return "ideographic space";
      case 0xfeff: return "byte-order mark";
      default: return "";
    }
  }

  Token lex() {
    skipSpaceAndComments();
    Token t;
    t.where = {file_, line_, column_, includedFrom_};
    if (done()) {
      t.type = Token::end;
    } else {
      const char c = at();
      auto single = [&](Token::Type ty) { t.type = ty; t.text = std::string(1, c); advance(); };
      switch (c) {
        case '{': single(Token::lbrace); break;
        case '}': single(Token::rbrace); break;
        case '(': single(Token::lparen); break;
        case ')': single(Token::rparen); break;
        case ';': single(Token::semicolon); break;
        case ']': throw InputError(t.where.str() + ": unexpected ']' with no matching '['");
        case '"': {
          advance();
          t.type = Token::string;
          while (!done() && at() != '"') {
            if (at() == '\\' && (at(1) == '"' || at(1) == '\\')) advance();
            t.text += at();
            advance();
          }
          if (done()) throw InputError(t.where.str() + ": string is never closed (missing '\"')");
          advance();
          break;
        }
        case '[': {
          advance();
          t.type = Token::unit;
          while (!done() && at() != ']' && at() != '\n' && at() != ';') { t.text += at(); advance(); }
          if (at() != ']') throw InputError(t.where.str() + ": unit '[' is never closed (missing ']')");
          advance();
          const auto b = t.text.find_first_not_of(" \t"), e = t.text.find_last_not_of(" \t");
          t.text = b == std::string::npos ? "" : t.text.substr(b, e - b + 1);
          break;
        }
        case '$':
          advance();
          t.type = Token::macro;
          t.text = wordChars();
          if (t.text.empty()) throw InputError(t.where.str() + ": expected a name after '$'");
          break;
        case '#':
          advance();
          t.type = Token::directive;
          t.text = wordChars();
          break;
        default:
          t.text = wordChars();
          t.type = Token::word;
          if (isNumber(t.text)) {
            t.type = Token::number;
            t.numberValue = std::strtod(t.text.c_str(), nullptr);
          }
      }
    }
    t.endLine = line_;
    t.endColumn = column_;
    return t;
  }
};

}  // namespace

class DictionaryParser {
 public:
  static Dictionary parse(const std::string& text, const std::string& file) {
    checkText(text, "file '" + file + "'");
    Dictionary root;
    root.name_ = file;
    root.where_ = {file, 0, 0, ""};
    DictionaryParser p;
    p.scope_.push_back(&root);
    Lexer lex(text, file);
    p.parseBody(lex, root, nullptr, "");
    // The FoamFile header is accepted and ignored.
    if (root.entries_.count("FoamFile")) {
      root.markRead("FoamFile");
      markAllRead(root.entries_.at("FoamFile"));
    }
    return root;
  }

 private:
  std::vector<Dictionary*> scope_;  // enclosing dictionaries, innermost last
  int includeDepth_ = 0;
  // Bounds that keep a hostile or broken file from exhausting the stack or
  // memory: nesting of { } and ( ), values made (macros copy), #includes.
  static constexpr int kMaxNesting = 200;
  static constexpr long kMaxValues = 500000;
  static constexpr int kMaxIncludes = 1000;
  int nesting_ = 0;
  long values_ = 0;
  int includes_ = 0;

  void enter(const SourceLocation& at, const std::string& key) {
    if (++nesting_ > kMaxNesting)
      fail(at, key, "dictionaries and lists nested more than " + std::to_string(kMaxNesting) + " deep");
  }
  void countValue(const SourceLocation& at, const std::string& key) {
    if (++values_ > kMaxValues)
      fail(at, key, "more than " + std::to_string(kMaxValues) + " values (do macros copy each other over and over?)");
  }

  [[noreturn]] static void fail(const SourceLocation& at, const std::string& key, const std::string& what) {
    throw InputError(at.str() + ": " + (key.empty() ? "" : "keyword '" + echoed(key) + "': ") + what);
  }

  // Entries until '}' (open != nullptr) or the end of the file.
  void parseBody(Lexer& lex, Dictionary& d, const Token* open, const std::string& dictKey) {
    for (;;) {
      Token t = lex.next();
      switch (t.type) {
        case Token::end:
          if (open)
            fail(open->where, dictKey, "'{' is never closed (reached the end of " + lex.file() + ")");
          return;
        case Token::rbrace:
          if (open) return;
          fail(t.where, "", "unexpected '}' with no matching '{'");
        case Token::semicolon:
          break;  // a stray ';' is harmless
        case Token::directive:
          directive(lex, d, t);
          break;
        case Token::macro: {
          // `$name;` merges the named dictionary into this one.
          const Token semi = lex.next();
          if (semi.type != Token::semicolon)
            fail(lex.lastEnd(), "", "expected ';' after $" + echoed(t.text) + ", found " + describe(semi));
          DictValue v = expand(t, "", d.name_);
          if (v.kind != DictValue::Kind::dict)
            fail(t.where, "", "$" + echoed(t.text) + " names a value, not a dictionary: only a dictionary can stand alone as an entry");
          for (const auto& k : v.dict->order_)
            add(d, k, v.dict->entries_.at(k), v.dict->keyLocation_.at(k));
          break;
        }
        case Token::word:
          entry(lex, d, t);
          break;
        default:
          fail(t.where, "", "expected a keyword, found " + describe(t));
      }
    }
  }

  void entry(Lexer& lex, Dictionary& d, const Token& keyTok) {
    const std::string& key = keyTok.text;
    const std::string path = d.name_ + "/" + key;
    const Token& first = lex.peek();
    if (first.type == Token::lbrace) {
      const Token open = lex.next();
      add(d, key, subDictionary(lex, open, path, keyTok.where, key), keyTok.where);
      return;
    }
    if (first.type == Token::semicolon)
      fail(first.where, key, "expected a value before ';'");
    if (first.type == Token::end || first.type == Token::rbrace)
      fail(lex.lastEnd(), key, "expected a value and ';', found " + describe(first));
    std::vector<DictValue> values;
    values.push_back(value(lex, lex.next(), key, path));
    for (;;) {
      const Token& p = lex.peek();
      if (p.type == Token::semicolon) { lex.next(); break; }
      if (p.type == Token::end || p.type == Token::rbrace || p.type == Token::lbrace ||
          p.type == Token::directive || p.where.line > lex.lastEnd().line)
        fail(lex.lastEnd(), key, "expected ';' after the value, found " + describe(p) +
             (p.where.line > lex.lastEnd().line ? " on the next line" : ""));
      if (p.type == Token::unit)
        fail(p.where, key, "a unit [" + p.text + "] must follow a number or a list");
      values.push_back(value(lex, lex.next(), key, path));
    }
    if (values.size() == 1) {
      add(d, key, std::move(values[0]), keyTok.where);
    } else {
      DictValue list;
      list.kind = DictValue::Kind::list;
      list.where = values[0].where;
      list.items = std::move(values);
      add(d, key, std::move(list), keyTok.where);
    }
  }

  // The sub-dictionary opened by `open` ('{', already read) up to its '}', as a
  // value: named `name` (its path), located at `where` (the keyword, or the brace
  // of a dictionary in a list).
  DictValue subDictionary(Lexer& lex, const Token& open, const std::string& name, const SourceLocation& where,
                          const std::string& key) {
    auto sub = std::make_shared<Dictionary>();
    sub->name_ = name;
    sub->where_ = where;
    scope_.push_back(sub.get());
    enter(open.where, key);
    parseBody(lex, *sub, &open, key);
    --nesting_;
    scope_.pop_back();
    DictValue v;
    v.kind = DictValue::Kind::dict;
    v.dict = sub;
    v.where = where;
    return v;
  }

  // One value starting with token t: number [unit], word, string, (list) [unit], $macro [unit].
  DictValue value(Lexer& lex, const Token& t, const std::string& key, const std::string& path) {
    DictValue v;
    v.where = t.where;
    v.text = t.text;
    countValue(t.where, key);
    switch (t.type) {
      case Token::number:
        v.kind = DictValue::Kind::number;
        v.number = t.numberValue;
        if (!std::isfinite(v.number))
          fail(t.where, key, "the number " + echoed(t.text) + " is out of range (a double holds up to about 1.8e308)");
        if (underflows(t.text, v.number))
          fail(t.where, key, "the number " + echoed(t.text) + " is out of range (too small: a double holds down to about "
                             "2.2e-308, and this would read as " + (v.number == 0 ? "0" : "a denormal") + ")");
        break;
      case Token::word: v.kind = DictValue::Kind::word; return v;
      case Token::string: v.kind = DictValue::Kind::string; return v;
      case Token::lparen: {
        v.kind = DictValue::Kind::list;
        v.text.clear();
        enter(t.where, key);
        for (;;) {
          const Token p = lex.next();
          if (p.type == Token::rparen) break;
          if (p.type == Token::end)
            fail(t.where, key, "'(' is never closed (reached the end of " + lex.file() + ")");
          if (p.type == Token::semicolon || p.type == Token::rbrace)
            fail(p.where, key, "expected ')' to close the list opened at line " +
                 std::to_string(t.where.line) + ", column " + std::to_string(t.where.column) +
                 ", found " + describe(p));
          const std::string itemPath = path + "/" + std::to_string(v.items.size());
          if (p.type == Token::lbrace) {
            v.items.push_back(subDictionary(lex, p, itemPath, p.where, key));
          } else {
            v.items.push_back(value(lex, p, key, itemPath));
          }
        }
        --nesting_;
        break;
      }
      case Token::macro: {
        const SourceLocation at = t.where;
        v = expand(t, key, path);
        v.where = at;
        break;
      }
      case Token::rparen: fail(t.where, key, "unexpected ')' with no matching '('");
      case Token::unit: fail(t.where, key, "a unit [" + echoed(t.text) + "] must follow a number or a list");
      case Token::directive: fail(t.where, key, "#" + echoed(t.text) + " may only stand where a keyword may");
      default: fail(t.where, key, "expected a value, found " + describe(t));
    }
    if (lex.peek().type == Token::unit) {
      const Token u = lex.next();
      if (v.kind != DictValue::Kind::number && v.kind != DictValue::Kind::list)
        fail(u.where, key, "a unit [" + u.text + "] must follow a number or a list");
      Unit unit;
      try {
        unit = parseUnit(u.text);
      } catch (const InputError& e) {
        fail(u.where, key, e.what());
      }
      applyUnit(v, unit, u, key);
    }
    return v;
  }

  // A number written nonzero that reads as 0 or a denormal (1e-400): out of range,
  // not silently zero.
  static bool underflows(const std::string& text, double x) {
    if (std::isnormal(x)) return false;
    for (char c : text) {
      if (c == 'e' || c == 'E') break;
      if (c >= '1' && c <= '9') return true;
    }
    return false;
  }

  static void applyUnit(DictValue& v, const Unit& unit, const Token& u, const std::string& key) {
    if (v.hasUnit) fail(u.where, key, "the value already has a unit [" + v.unitText + "]");
    if (v.kind == DictValue::Kind::number) {
      v.number *= unit.factor;
      if (!std::isfinite(v.number) || underflows(v.text, v.number))
        fail(u.where, key, "the number " + echoed(v.text) + " [" + echoed(u.text) + "] is out of range in SI units");
    } else if (v.kind == DictValue::Kind::list) {
      for (auto& item : v.items) applyUnit(item, unit, u, key);
    } else {
      fail(u.where, key, "a unit [" + u.text + "] applies to numbers, but the list holds " +
           (v.kind == DictValue::Kind::dict ? std::string("a dictionary") : "'" + echoed(v.text) + "'"));
    }
    v.hasUnit = true;
    v.unitDim = unit.dim;
    v.unitText = u.text;
  }

  // $name or $sub/name: an entry defined earlier in this or an enclosing
  // dictionary. The source entry counts as read; a dictionary is deep-copied.
  DictValue expand(const Token& t, const std::string& key, const std::string& path) {
    std::vector<std::string> parts;
    std::stringstream ss(t.text);
    for (std::string p; std::getline(ss, p, '/');)
      if (!p.empty()) parts.push_back(p);
    if (parts.empty()) fail(t.where, key, "empty macro name $" + echoed(t.text));
    const DictValue* v = nullptr;
    Dictionary* owner = nullptr;
    for (auto it = scope_.rbegin(); it != scope_.rend() && !v; ++it) {
      auto e = (*it)->entries_.find(parts[0]);
      if (e != (*it)->entries_.end()) { v = &e->second; owner = *it; }
    }
    if (!v) {
      std::vector<std::string> visible;
      for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
        visible.insert(visible.end(), (*it)->order_.begin(), (*it)->order_.end());
      notFound(t, key, parts[0], visible);
    }
    owner->queried_.insert(parts[0]);
    for (std::size_t k = 1; k < parts.size(); ++k) {
      if (v->kind != DictValue::Kind::dict)
        fail(t.where, key, "macro $" + echoed(t.text) + ": '" + parts[k - 1] + "' is not a dictionary");
      const Dictionary& sub = *v->dict;
      auto e = sub.entries_.find(parts[k]);
      if (e == sub.entries_.end()) notFound(t, key, parts[k], sub.order_);
      sub.queried_.insert(parts[k]);
      v = &e->second;
    }
    markAllRead(*v);
    return clone(*v, path, t.where, key);
  }

  [[noreturn]] static void notFound(const Token& t, const std::string& key, const std::string& part,
                                    const std::vector<std::string>& candidates) {
    std::string m = "macro $" + echoed(t.text) + " not found ('" + part + "' is not defined before it)";
    const std::string near = closestMatch(part, candidates);
    if (!near.empty()) {
      std::string fixed = t.text;
      fixed.replace(fixed.find(part), part.size(), near);
      m += "; did you mean '$" + fixed + "'?";
    }
    fail(t.where, key, m);
  }

  static void markAllRead(const DictValue& v) {
    if (v.kind == DictValue::Kind::dict)
      for (const auto& k : v.dict->order_) {
        v.dict->queried_.insert(k);
        markAllRead(v.dict->entries_.at(k));
      }
    for (const auto& item : v.items) markAllRead(item);
  }

  DictValue clone(const DictValue& v, const std::string& name, const SourceLocation& at, const std::string& key) {
    countValue(at, key);
    DictValue c = v;
    if (v.kind == DictValue::Kind::dict) {
      auto d = std::make_shared<Dictionary>();
      d->name_ = name;
      d->where_ = v.dict->where_;
      d->order_ = v.dict->order_;
      d->keyLocation_ = v.dict->keyLocation_;
      for (const auto& [k, e] : v.dict->entries_) d->entries_[k] = clone(e, name + "/" + k, at, key);
      c.dict = d;
    }
    for (std::size_t i = 0; i < v.items.size(); ++i) c.items[i] = clone(v.items[i], name + "/" + std::to_string(i), at, key);
    return c;
  }

  // A repeated keyword replaces the earlier value (keeping its place in the
  // order); two sub-dictionaries of the same name are merged, recursively.
  // Sub-dictionaries arrive already named after their path.
  static void add(Dictionary& d, const std::string& key, DictValue v, const SourceLocation& at) {
    auto it = d.entries_.find(key);
    if (it == d.entries_.end()) {
      d.order_.push_back(key);
      d.entries_[key] = std::move(v);
      d.keyLocation_[key] = at;
      return;
    }
    if (it->second.kind == DictValue::Kind::dict && v.kind == DictValue::Kind::dict) {
      Dictionary& dst = *it->second.dict;
      dst.queried_.insert(v.dict->queried_.begin(), v.dict->queried_.end());
      for (const auto& k : v.dict->order_) add(dst, k, v.dict->entries_.at(k), v.dict->keyLocation_.at(k));
      return;
    }
    it->second = std::move(v);
    d.keyLocation_[key] = at;
  }

  void directive(Lexer& lex, Dictionary& d, const Token& t) {
    const bool optional = t.text == "includeIfPresent";
    if (t.text != "include" && !optional) {
      std::string m = "unknown directive '#" + echoed(t.text) + "'";
      const std::string near = closestMatch(t.text, {"include", "includeIfPresent"});
      fail(t.where, "", m + (near.empty() ? " (known: #include, #includeIfPresent)"
                                          : "; did you mean '#" + near + "'?"));
    }
    const Token f = lex.next();
    if (f.type != Token::string && f.type != Token::word)
      fail(f.where, "", "expected a quoted file name after #" + echoed(t.text) + ", found " + describe(f));
    if (lex.peek().type == Token::semicolon) lex.next();
    std::filesystem::path file(f.text);
    if (file.is_relative()) file = std::filesystem::path(lex.file()).parent_path() / file;
    const std::string resolved = file.lexically_normal().string();
    std::string text;
    std::error_code ec;
    if (std::filesystem::exists(resolved, ec) && !std::filesystem::is_regular_file(resolved, ec))
      fail(t.where, "", "#" + t.text + " \"" + echoed(f.text) + "\": '" + resolved + "' is not a regular file (a directory?)");
    if (!readFile(resolved, text)) {
      if (optional) return;
      fail(t.where, "", "#include \"" + echoed(f.text) + "\": cannot open file '" + resolved + "'");
    }
    if (++includes_ > kMaxIncludes)
      fail(t.where, "", "more than " + std::to_string(kMaxIncludes) + " #include directives in one dictionary");
    if (includeDepth_ >= 32)
      fail(t.where, "", "#include \"" + echoed(f.text) + "\" nested more than 32 deep (does a file include itself?)");
    // Every location inside the included file names this #include (and its own chain).
    // Two levels of the chain are named, deeper ones summarised (an include loop is 32 deep).
    std::string from = SourceLocation{t.where.file, t.where.line, t.where.column, ""}.str();
    const std::string& up = t.where.includedFrom;
    const std::size_t second = up.find(", included from ");
    if (!up.empty()) from += ", included from " + (second == std::string::npos ? up : up.substr(0, second) + ", ...");
    checkText(text, "file '" + resolved + "' (included from " + from + ")");
    ++includeDepth_;
    Lexer sub(std::move(text), resolved, from);
    parseBody(sub, d, nullptr, "");
    --includeDepth_;
  }

 public:
  static bool read(const std::string& path, std::string& text) { return readFile(path, text); }
};

std::string SourceLocation::str() const {
  const std::string from = includedFrom.empty() ? "" : " (included from " + includedFrom + ")";
  if (line <= 0) return file + from;
  return file + ":" + std::to_string(line) + ":" + std::to_string(column) + from;
}

Dictionary Dictionary::fromString(const std::string& text, const std::string& name) {
  return DictionaryParser::parse(text, name);
}

Dictionary Dictionary::fromFile(const std::string& path) {
  std::string text;
  if (!DictionaryParser::read(path, text)) throw InputError("cannot open file '" + path + "' (missing or unreadable)");
  return DictionaryParser::parse(text, path);
}

Dictionary Dictionary::fromFileIfPresent(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    Dictionary d;
    d.name_ = path;
    d.where_ = {path, 0, 0, ""};
    return d;
  }
  return fromFile(path);
}

}  // namespace shizuku
