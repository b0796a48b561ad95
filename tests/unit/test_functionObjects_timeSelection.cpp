// Command-line time selection of shizukuPostProcess (TimeSelection.hpp):
// lists, ranges with open ends, latestTime/firstTime/all, tolerance on
// accumulated times, errors naming the saved times.
#define BOOST_TEST_MODULE functionObjects_timeSelection
#include <boost/test/unit_test.hpp>

#include "core/types.hpp"
#include "functionObjects/TimeSelection.hpp"

using namespace shizuku;

namespace {
const std::vector<std::pair<double, std::string>> saved{
    {0, "0"}, {0.1, "0.1"}, {0.2, "0.2"}, {0.30000000000000004, "0.3"}, {0.4, "0.4"}, {1e-05 + 1, "1.00001"}};

std::vector<std::string> names(const std::string& sel) {
  std::vector<std::string> n;
  for (const auto& t : selectTimes(saved, sel)) n.push_back(t.second);
  return n;
}
using V = std::vector<std::string>;
}  // namespace

BOOST_AUTO_TEST_CASE(selections) {
  BOOST_TEST(names("") == V({"0", "0.1", "0.2", "0.3", "0.4", "1.00001"}), boost::test_tools::per_element());
  BOOST_TEST(names("all").size() == 6);
  BOOST_TEST(names("0.2,0.1") == V({"0.1", "0.2"}), boost::test_tools::per_element());
  BOOST_TEST(names("0.3") == V({"0.3"}), boost::test_tools::per_element());         // 0.30000000000000004 saved
  BOOST_TEST(names("0.1:0.3") == V({"0.1", "0.2", "0.3"}), boost::test_tools::per_element());
  BOOST_TEST(names(":0.1") == V({"0", "0.1"}), boost::test_tools::per_element());
  BOOST_TEST(names("0.35:") == V({"0.4", "1.00001"}), boost::test_tools::per_element());
  BOOST_TEST(names("latestTime") == V({"1.00001"}), boost::test_tools::per_element());
  BOOST_TEST(names("firstTime, latestTime, 0.4") == V({"0", "0.4", "1.00001"}), boost::test_tools::per_element());
  BOOST_TEST(names("0.1,0.1:0.2") == V({"0.1", "0.2"}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(errors) {
  BOOST_CHECK_THROW(selectTimes(saved, "0.15"), InputError);
  BOOST_CHECK_THROW(selectTimes(saved, "0.11:0.19"), InputError);
  BOOST_CHECK_THROW(selectTimes(saved, "abc"), InputError);
  BOOST_CHECK_THROW(selectTimes(saved, "0.1,,0.2"), InputError);
  BOOST_CHECK_THROW(selectTimes(saved, "x:0.2"), InputError);
  BOOST_CHECK_THROW(selectTimes({}, "latestTime"), InputError);
  // Non-finite times would match every saved time through the tolerance: refused, named.
  for (const char* bad : {"inf", "inf:", ":inf", "-inf:", "nan", "0:nan", "Infinity", "0.1,inf"}) {
    BOOST_TEST_INFO(bad);
    const std::string m = [&] {
      try {
        selectTimes(saved, bad);
      } catch (const InputError& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    }();
    BOOST_TEST(m.find("is not a finite time") != std::string::npos, m);
  }
  try {
    selectTimes(saved, "0.15");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("saved times: 0 0.1 0.2 0.3 0.4 1.00001") != std::string::npos);
  }
}
