// Test helper: the message of the exception a call throws, so that a test can
// check what an error names; "" when the call throws none (or another type).
#pragma once
#include "core/types.hpp"
#include <string>

namespace shizuku::test {

template <class E = InputError, class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace shizuku::test
