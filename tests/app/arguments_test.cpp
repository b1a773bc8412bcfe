// The shared command-line parser: the rules both programs follow, mistake by mistake.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/common/arguments.h"

namespace ydscope {
namespace {

Arguments parse(std::vector<std::string> args, std::size_t max_positionals = 0) {
  return Arguments(args, {"port", "format", "laps", "filter", "distance-scale"}, {"verbose"}, max_positionals);
}

std::string mistake(std::vector<std::string> args, std::size_t max_positionals = 0) {
  try {
    parse(std::move(args), max_positionals);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(Arguments, ValuesComeSeparateOrAfterAnEqualsSign) {
  const auto args = parse({"--port", "/dev/ttyUSB0", "--format=csv", "--verbose", "--laps=", "--filter=a=b"});
  EXPECT_EQ(args.value("port"), "/dev/ttyUSB0");
  EXPECT_EQ(args.value("format"), "csv");
  EXPECT_EQ(args.value("laps"), "");
  EXPECT_EQ(args.value("filter"), "a=b");
  EXPECT_TRUE(args.has("verbose"));
  EXPECT_FALSE(args.has("distance-scale"));
}

TEST(Arguments, NegativeNumbersAndDashAreValuesNotOptions) {
  const auto args = parse({"--distance-scale", "-0.5", "-"}, 1);
  EXPECT_EQ(args.value("distance-scale"), "-0.5");
  EXPECT_EQ(args.positionals(), std::vector<std::string>{"-"});
}

TEST(Arguments, DoubleDashEndsTheOptions) {
  const auto args = parse({"--verbose", "--", "--port"}, 1);
  EXPECT_EQ(args.positionals(), std::vector<std::string>{"--port"});
  EXPECT_FALSE(args.value("port"));
  EXPECT_FALSE(parse({"--", "-h"}, 1).help_requested());
}

TEST(Arguments, HelpAndVersionHaveShortAndLongForms) {
  EXPECT_TRUE(parse({"-h"}).help_requested());
  EXPECT_TRUE(parse({"--help"}).help_requested());
  EXPECT_TRUE(parse({"-V"}).version_requested());
  EXPECT_TRUE(parse({"--version"}).version_requested());
  const std::vector<std::string> help_then_mistake{"--port", "x", "--help", "--nonsense"};
  EXPECT_TRUE(asks_for_help(help_then_mistake));
  EXPECT_FALSE(asks_for_version(help_then_mistake));
  EXPECT_FALSE(asks_for_help(std::vector<std::string>{"--", "--help"}));
}

TEST(Arguments, NearMissesGetASuggestion) {
  EXPECT_EQ(mistake({"--fromat", "csv"}), "unknown option --fromat; did you mean --format?");
  EXPECT_EQ(mistake({"--lap", "3"}), "unknown option --lap; did you mean --laps?");
  EXPECT_EQ(mistake({"--distance=2"}), "unknown option --distance; did you mean --distance-scale?");
  EXPECT_EQ(mistake({"-p", "/dev/ttyUSB0"}), "unknown option -p; did you mean --port?");
  EXPECT_EQ(mistake({"-port", "/dev/ttyUSB0"}), "unknown option -port; did you mean --port?");
  EXPECT_EQ(mistake({"--versoin"}), "unknown option --versoin; did you mean --version?");
}

TEST(Arguments, FarMissesAndAmbiguityPointToTheHelp) {
  EXPECT_EQ(mistake({"--colour"}), "unknown option --colour; see --help for the options");
  EXPECT_EQ(mistake({"-f"}), "unknown option -f; see --help for the options") << "--format or --filter";
  EXPECT_EQ(mistake({"-x"}), "unknown option -x; see --help for the options");
}

TEST(Arguments, StrayArgumentsAreErrors) {
  EXPECT_EQ(mistake({"--port", "x", "garbage"}),
            "unexpected argument 'garbage': this command takes only options (see --help)");
  EXPECT_EQ(mistake({"a.bin", "b.bin"}, 1), "unexpected argument 'b.bin' after 'a.bin' (see --help)");
  EXPECT_EQ(mistake({"--port", "x", "laps", "3"}), "unexpected argument 'laps'; did you mean --laps?");
}

TEST(Arguments, ValueMistakes) {
  EXPECT_EQ(mistake({"--port"}), "option --port needs a value (--port VALUE or --port=VALUE)");
  EXPECT_EQ(mistake({"--port", "--verbose"}), "option --port needs a value (--port VALUE or --port=VALUE)");
  EXPECT_EQ(mistake({"--port", "a", "--port", "b"}), "option --port is given twice");
  EXPECT_EQ(mistake({"--verbose=yes"}), "option --verbose takes no value");
  EXPECT_THROW(parse({"--laps", "x"}).integer("laps", 1, 10), UsageError);
  EXPECT_THROW(parse({"--laps", "11"}).integer("laps", 1, 10), UsageError);
  EXPECT_EQ(parse({"--laps", "10"}).integer("laps", 1, 10), 10);
  EXPECT_THROW(parse({}).required("port"), UsageError);
}

TEST(ClosestMatch, PicksOneCandidateOrNone) {
  const std::vector<std::string> commands{"decode", "info", "ports", "record", "replay", "scan", "set", "sim"};
  EXPECT_EQ(closest_match("scna", commands), "scan");
  EXPECT_EQ(closest_match("decdoe", commands), "decode");
  EXPECT_EQ(closest_match("rec", commands), "record");
  EXPECT_EQ(closest_match("re", commands), std::nullopt) << "record or replay";
  EXPECT_EQ(closest_match("s", commands), std::nullopt) << "scan, set or sim";
  EXPECT_EQ(closest_match("sin", commands), "sim");
  EXPECT_EQ(closest_match("calibrate", commands), std::nullopt);
  EXPECT_EQ(closest_match("", commands), std::nullopt);
}

}  // namespace
}  // namespace ydscope
