// Every service reads its --key value options by the same rules: a value that does not parse
// whole, is not finite or lies outside its range is an OptionError naming the flag; an absent
// key gives the default.
#include "common/service/options.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "common/service/option_catalogue.h"

namespace hexplore::service {
namespace {

// The parsing rules are the same for every key; the tests read catalogued ones (Options refuses
// any other), kAny standing for any of them.
const std::string kAny = "cycle-ms";

std::string problem_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "--cycle-ms");
    return e.problem();
  }
  ADD_FAILURE() << "no OptionError";
  return {};
}

TEST(ServiceOptions, AbsentKeysGiveTheirDefaults) {
  const Options::Arguments args;
  const Options o(args);
  EXPECT_FALSE(o.has(kAny));
  EXPECT_EQ(o.number(kAny, 1.5, 0.0, 2.0), 1.5);
  EXPECT_EQ(o.positive(kAny, 3.0), 3.0);
  EXPECT_EQ(o.integer(kAny, 4, 1), 4);
  EXPECT_TRUE(o.flag(kAny, true));
  EXPECT_EQ(o.text(kAny, "dir"), "dir");
  EXPECT_EQ(o.choice(kAny, "sim", {"sim", "wall"}), "sim");
}

TEST(ServiceOptions, GoodValuesAreRead) {
  const Options::Arguments args = {{"reach-m", "0.25"},     {"give-up-views", "3"},    {"observe", "yes"},
                                     {"report", "0"},         {"decision-clock", "wall"}, {"trace-dir", "a b"}};
  const Options o(args);
  EXPECT_EQ(o.number("reach-m", 0.0, 0.0, 1.0), 0.25);
  EXPECT_EQ(o.positive("reach-m", 1.0), 0.25);
  EXPECT_EQ(o.integer("give-up-views", 0, 1, 5), 3);
  EXPECT_TRUE(o.flag("observe", false));
  EXPECT_FALSE(o.flag("report", true));
  EXPECT_EQ(o.choice("decision-clock", "sim", {"sim", "wall"}), "wall");
  EXPECT_EQ(o.text("trace-dir"), "a b");
}

TEST(ServiceOptions, BadValuesNameTheFlagAndSayWhatWasExpected) {
  auto with = [](const std::string& value) { return Options::Arguments{{kAny, value}}; };
  for (const char* bad : {"", "abc", "1.5s", "nan", "inf", "2 "}) {
    const auto args = with(bad);
    EXPECT_NE(problem_of([&] { Options(args).number(kAny, 0.0); }).find("expects a number"), std::string::npos) << bad;
  }
  const auto low = with("-1");
  EXPECT_EQ(problem_of([&] { Options(low).number(kAny, 0.0, 0.0); }), "expects a number >= 0, got '-1'");
  EXPECT_EQ(problem_of([&] { Options(low).number(kAny, 0.0, 0.0, 10.0); }), "expects a number in [0, 10], got '-1'");
  const auto zero = with("0");
  EXPECT_EQ(problem_of([&] { Options(zero).positive(kAny, 1.0); }), "expects a positive number, got '0'");
  const auto half = with("2.5");
  EXPECT_EQ(problem_of([&] { Options(half).integer(kAny, 1, 1); }), "expects a whole number, got '2.5'");
  const auto maybe = with("maybe");
  EXPECT_EQ(problem_of([&] { Options(maybe).flag(kAny, false); }), "expects true or false, got 'maybe'");
  EXPECT_EQ(problem_of([&] { Options(maybe).choice(kAny, "sim", {"sim", "wall"}); }),
            "expects one of sim, wall, got 'maybe'");
}

// A key missing from the catalogue is a bug of the service that reads it, not bad input.
TEST(ServiceOptions, ReadingAKeyTheCatalogueLacksIsABug) {
  const Options::Arguments args = {{"no-such-option", "1"}};
  EXPECT_THROW(Options(args).number("no-such-option", 0.0), std::logic_error);
  EXPECT_THROW(Options(args).has("no-such-option"), std::logic_error);
}

TEST(OptionCatalogue, EveryNameOnceInOrderWithWhoReadsItAndWhatItDoes) {
  const auto& table = service_option_catalogue();
  ASSERT_FALSE(table.empty());
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_FALSE(table[i].services.empty()) << table[i].name;
    EXPECT_FALSE(table[i].summary.empty()) << table[i].name;
    if (i > 0) EXPECT_LT(table[i - 1].name, table[i].name) << "out of order or twice";
  }
  EXPECT_NE(service_options_help().find("--trace-dir"), std::string::npos);
}

TEST(OptionCatalogue, AServiceFromOutsideTheTreeAddsItsOwnButNoSecondMeaningOfOne) {
  EXPECT_FALSE(is_service_option("my-planner-depth"));
  add_service_options({{"my-planner-depth", "planning", "search depth of a planner of one's own"}});
  EXPECT_TRUE(is_service_option("my-planner-depth"));
  EXPECT_NO_THROW(require_service_options({{"my-planner-depth", "3"}}));
  EXPECT_THROW(add_service_options({{"trace-dir", "planning", "another meaning"}}), std::logic_error);
}

TEST(OptionCatalogue, AnUnknownKeyIsAnOptionErrorWithTheNearestName) {
  EXPECT_NO_THROW(require_service_options({{"results", "r"}, {"trace-dir", "t"}}));
  try {
    require_service_options({{"results", "r"}, {"settle-s", "5"}});
    ADD_FAILURE() << "accepted --settle-s";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "--settle-s");
    EXPECT_NE(e.problem().find("did you mean --end-settle-s?"), std::string::npos) << e.problem();
  }
  // Nothing near: no guess.
  EXPECT_EQ(unknown_option_message("xyzzy").find("did you mean"), std::string::npos);
}

}  // namespace
}  // namespace hexplore::service
