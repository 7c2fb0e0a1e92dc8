// Every service reads its --key value options by the same rules: a value that does not parse
// whole, is not finite or lies outside its range is an OptionError naming the flag; an absent
// key gives the default.
#include "common/service/options.h"

#include <gtest/gtest.h>

namespace hexplore::service {
namespace {

std::string problem_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "--x");
    return e.problem();
  }
  ADD_FAILURE() << "no OptionError";
  return {};
}

TEST(ServiceOptions, AbsentKeysGiveTheirDefaults) {
  const Options::Arguments args;
  const Options o(args);
  EXPECT_FALSE(o.has("x"));
  EXPECT_EQ(o.number("x", 1.5, 0.0, 2.0), 1.5);
  EXPECT_EQ(o.positive("x", 3.0), 3.0);
  EXPECT_EQ(o.integer("x", 4, 1), 4);
  EXPECT_TRUE(o.flag("x", true));
  EXPECT_EQ(o.text("x", "dir"), "dir");
  EXPECT_EQ(o.choice("x", "sim", {"sim", "wall"}), "sim");
}

TEST(ServiceOptions, GoodValuesAreRead) {
  const Options::Arguments args = {{"n", "0.25"}, {"i", "3"}, {"yes", "yes"}, {"off", "0"}, {"c", "wall"}, {"t", "a b"}};
  const Options o(args);
  EXPECT_EQ(o.number("n", 0.0, 0.0, 1.0), 0.25);
  EXPECT_EQ(o.positive("n", 1.0), 0.25);
  EXPECT_EQ(o.integer("i", 0, 1, 5), 3);
  EXPECT_TRUE(o.flag("yes", false));
  EXPECT_FALSE(o.flag("off", true));
  EXPECT_EQ(o.choice("c", "sim", {"sim", "wall"}), "wall");
  EXPECT_EQ(o.text("t"), "a b");
}

TEST(ServiceOptions, BadValuesNameTheFlagAndSayWhatWasExpected) {
  auto with = [](const std::string& value) { return Options::Arguments{{"x", value}}; };
  for (const char* bad : {"", "abc", "1.5s", "nan", "inf", "2 "}) {
    const auto args = with(bad);
    EXPECT_NE(problem_of([&] { Options(args).number("x", 0.0); }).find("expects a number"), std::string::npos) << bad;
  }
  const auto low = with("-1");
  EXPECT_EQ(problem_of([&] { Options(low).number("x", 0.0, 0.0); }), "expects a number >= 0, got '-1'");
  EXPECT_EQ(problem_of([&] { Options(low).number("x", 0.0, 0.0, 10.0); }), "expects a number in [0, 10], got '-1'");
  const auto zero = with("0");
  EXPECT_EQ(problem_of([&] { Options(zero).positive("x", 1.0); }), "expects a positive number, got '0'");
  const auto half = with("2.5");
  EXPECT_EQ(problem_of([&] { Options(half).integer("x", 1, 1); }), "expects a whole number, got '2.5'");
  const auto maybe = with("maybe");
  EXPECT_EQ(problem_of([&] { Options(maybe).flag("x", false); }), "expects true or false, got 'maybe'");
  EXPECT_EQ(problem_of([&] { Options(maybe).choice("x", "sim", {"sim", "wall"}); }),
            "expects one of sim, wall, got 'maybe'");
}

}  // namespace
}  // namespace hexplore::service
