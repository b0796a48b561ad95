// Fuzz target: the case-dictionary reader (libsph/core/Dictionary*).
//
// Input: the text of one dictionary file. It is parsed with
// Dictionary::fromString, then every entry is read back through every typed
// getter (scalar, int, vectors in 1-3 D, matrices, words, options, switches,
// lists), recursively into sub-dictionaries, and checkAllRead() is called.
// Bad input must end in InputError; anything else (another exception, a
// sanitizer report, a crash, a hang) is a bug.
//
// Built two ways (fuzz/CMakeLists.txt): with clang -fsanitize=fuzzer as a
// libFuzzer target (fuzz/run-fuzzers), and with any compiler linked to
// replay_main.cpp, which runs the committed corpus as a ctest.
#include "core/Dictionary.hpp"
#include <cstddef>
#include <cstdint>
#include <string>

using namespace shizuku;

namespace {

// The reader follows #include: keep it to files beside the input (none
// exist), never a special or huge file elsewhere (a fuzzed
// "#include \"/proc/kcore\"" would read for ever). Inputs that mention
// include and hold a '/' outside comment markers, or "..", are skipped.
bool mayOpenOtherFiles(const std::string& text) {
  if (text.find("include") == std::string::npos) return false;
  if (text.find("..") != std::string::npos) return true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '/') continue;
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    const char prev = i > 0 ? text[i - 1] : '\0';
    if (next == '/' || next == '*' || prev == '/' || prev == '*') continue;
    return true;
  }
  return false;
}

template <class F> void tryRead(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

void readAll(const Dictionary& d, int depth) {
  if (depth > 64) return;
  for (const std::string& key : d.keys()) {
    tryRead([&] { d.getScalar(key, dim::length); });
    tryRead([&] { d.getScalarOr(key, 1.0, dim::none); });
    tryRead([&] { d.getInt(key); });
    tryRead([&] { d.getVector<1>(key, dim::none); });
    tryRead([&] { d.getVector<2>(key, dim::velocity); });
    tryRead([&] { d.getVector<3>(key, dim::none); });
    tryRead([&] { d.getMatrix<2>(key, dim::inverseTime); });
    tryRead([&] { d.getMatrix<3>(key, dim::none); });
    tryRead([&] { d.getVectorList<2>(key, dim::length); });
    tryRead([&] { d.getScalarList(key, dim::none); });
    tryRead([&] { d.getWord(key); });
    tryRead([&] { d.getWordList(key); });
    tryRead([&] { d.getOption(key, {"box", "circle", "fluid", "wall"}); });
    tryRead([&] { d.getSwitch(key); });
    tryRead([&] { d.location(key).str(); });
    if (d.isDict(key)) readAll(d.subDict(key), depth + 1);
  }
  tryRead([&] { d.getWordOr("absentWord", "x"); });
  tryRead([&] { d.getScalar("absentScalar", dim::time); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (mayOpenOtherFiles(text)) return 0;
  try {
    const Dictionary d = Dictionary::fromString(text, "fuzz/system/controlDict");
    tryRead([&] { d.checkAllRead(); });
    readAll(d, 0);
    d.checkAllRead();
  } catch (const InputError&) {
  }
  Dictionary::defaultsUsed().clear();  // a log of every default: keep it from growing across inputs
  return 0;
}
