// Several shared lidars' parameters: each under its name, and a set reaches that lidar only.
#include "core/bridge/sources_parameters.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace ydscope::foxglove {
namespace {

struct SetOutcome {
  std::vector<Parameter> read_back;
  std::string error;
};

// The filter parameters answer at once (no device involved), so the callback has run on return.
SetOutcome set(SourcesParameters& parameters, const std::string& name, bool value) {
  SetOutcome outcome;
  parameters.set({name, value}, [&](std::vector<Parameter> read_back, std::string error) {
    outcome = {std::move(read_back), std::move(error)};
  });
  return outcome;
}

bool has(const std::vector<Parameter>& list, const std::string& name) {
  return std::any_of(list.begin(), list.end(), [&](const Parameter& p) { return p.name == name; });
}

class SourcesParametersTest : public ::testing::Test {
 protected:
  SourcesParametersTest() {
    named.add("front", &front);
    named.add("back", &back);
  }
  Session front_session{4};
  Session back_session{4};
  SessionParameters front{front_session};
  SessionParameters back{back_session};
  SourcesParameters named;
};

TEST_F(SourcesParametersTest, EveryLidarsParametersAreListedUnderItsName) {
  const std::vector<Parameter> all = named.current();
  EXPECT_TRUE(has(all, "front/filter_specular"));
  EXPECT_TRUE(has(all, "back/filter_ambient"));
  EXPECT_FALSE(has(all, "filter_ambient"));
}

TEST_F(SourcesParametersTest, ASetReachesTheNamedLidarOnlyAndReadsBackUnderItsName) {
  const SetOutcome outcome = set(named, "back/filter_ambient", true);
  EXPECT_EQ(outcome.error, "");
  ASSERT_EQ(outcome.read_back.size(), 1u);
  EXPECT_EQ(outcome.read_back[0].name, "back/filter_ambient");
  EXPECT_TRUE(back.filter().ambient_light);
  EXPECT_FALSE(front.filter().ambient_light);
}

TEST_F(SourcesParametersTest, ANameWithoutAKnownLidarIsRefusedNamingTheLidars) {
  for (const std::string name : {"filter_ambient", "side/filter_ambient", "fronts/filter_ambient", "/filter_ambient"}) {
    const SetOutcome outcome = set(named, name, true);
    EXPECT_NE(outcome.error.find("no parameter \"" + name + "\""), std::string::npos) << outcome.error;
    EXPECT_NE(outcome.error.find("front, back"), std::string::npos) << outcome.error;
  }
  // A client's 64 KiB name is quoted short, not sent back whole (bridge abuse, issue 26).
  const SetOutcome huge = set(named, std::string(65536, 'x'), true);
  EXPECT_LT(huge.error.size(), 300u) << huge.error.substr(0, 300);
  EXPECT_NE(huge.error.find("(65536 bytes)"), std::string::npos) << huge.error.substr(0, 300);
  EXPECT_FALSE(front.filter().ambient_light);
  EXPECT_FALSE(back.filter().ambient_light);
}

}  // namespace
}  // namespace ydscope::foxglove
