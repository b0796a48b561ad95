// Test helper: the message of the exception a call throws, so that a test can
// check what an error names; "" when the call throws none (or another type).
// CHECK_MESSAGE(msg, "part", ...): msg is not empty and contains every part (Boost.Test).
#pragma once
#include "core/types.hpp"
#include <string>
#include <vector>

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

#define CHECK_MESSAGE(msg, ...)                                                            \
  do {                                                                                     \
    const std::string m_ = (msg);                                                          \
    BOOST_TEST_INFO("message: " << m_);                                                    \
    BOOST_CHECK(!m_.empty());                                                              \
    for (const std::string& part_ : std::vector<std::string>{__VA_ARGS__}) {               \
      BOOST_TEST_INFO("message: '" << m_ << "' should contain '" << part_ << "'");         \
      BOOST_CHECK(m_.find(part_) != std::string::npos);                                    \
    }                                                                                      \
  } while (0)
