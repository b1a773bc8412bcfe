// Identity by serial (core/frame/unit_identity.h): names and poses follow the serial to the port it
// is on, and what moved is said.
#include "core/frame/unit_identity.h"

#include <gtest/gtest.h>

namespace ydscope {
namespace {

SourceInfo bound(std::string name, Pose pose, std::string serial) {
  SourceInfo source;
  source.name = std::move(name);
  source.pose = pose;
  source.serial = std::move(serial);
  return source;
}

const Pose kFront{0.3, 0.0, 0.0};
const Pose kRear{-0.4, 0.1, 180.0};

TEST(UnitIdentity, UnitsOnTheirOwnPortsChangeNothingAndSayNothing) {
  const auto result = identify_units({bound("front", kFront, "1111"), bound("rear", kRear, "2222")},
                                     {{"/dev/A", "1111"}, {"/dev/B", "2222"}});
  ASSERT_EQ(result.sources.size(), 2u);
  EXPECT_EQ(result.sources[0].name, "front");
  EXPECT_EQ(result.sources[1].name, "rear");
  EXPECT_FALSE(result.moved);
  EXPECT_TRUE(result.notes.empty());
}

TEST(UnitIdentity, TwoSwappedUnitsKeepTheirNamesAndPosesAndTheSwapIsSaidOnce) {
  const auto result = identify_units({bound("front", kFront, "1111"), bound("rear", kRear, "2222")},
                                     {{"/dev/A", "2222"}, {"/dev/B", "1111"}});
  EXPECT_TRUE(result.moved);
  EXPECT_EQ(result.sources[0].name, "rear");
  EXPECT_EQ(result.sources[0].pose, kRear);
  EXPECT_EQ(result.sources[0].serial, "2222");
  EXPECT_EQ(result.sources[1].name, "front");
  EXPECT_EQ(result.sources[1].pose, kFront);
  EXPECT_EQ(result.sources[1].serial, "1111");
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(result.notes[0],
            "rear (serial 2222) and front (serial 1111) have swapped ports: rear is on /dev/A, front on /dev/B; "
            "each keeps its name and pose");
}

TEST(UnitIdentity, AUnitMovedToAnotherPortTakesItsNameThereAndThePortBoundOneMakesRoom) {
  // front is bound by serial; side is bound by its port. front's unit came up on side's port.
  const auto result = identify_units({bound("front", kFront, "1111"), bound("side", kRear, "")},
                                     {{"/dev/A", "3333"}, {"/dev/B", "1111"}});
  EXPECT_EQ(result.sources[1].name, "front");
  EXPECT_EQ(result.sources[1].pose, kFront);
  EXPECT_EQ(result.sources[0].name, "side");
  EXPECT_EQ(result.sources[0].serial, "3333");
  ASSERT_EQ(result.notes.size(), 2u);
  EXPECT_EQ(result.notes[0], "side is on /dev/A now: its port /dev/B holds front's unit");
  EXPECT_EQ(result.notes[1], "front (serial 1111) is on /dev/B now, not /dev/A; it keeps its name and pose");
}

TEST(UnitIdentity, AStrangerOnABoundPortIsTakenAsItsSourceAndSaid) {
  const auto result = identify_units({bound("front", kFront, "1111"), bound("rear", kRear, "2222")},
                                     {{"/dev/A", "9999"}, {"/dev/B", "2222"}});
  EXPECT_FALSE(result.moved);
  EXPECT_EQ(result.sources[0].name, "front");
  EXPECT_EQ(result.sources[0].serial, "9999");
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(
      result.notes[0],
      "front is bound to serial 1111, which no port's unit has; the unit on /dev/A (serial 9999) is taken as front");
}

TEST(UnitIdentity, WithoutSerialsEveryLidarStaysOnItsPort) {
  const auto result =
      identify_units({bound("front", kFront, ""), bound("rear", kRear, "")}, {{"/dev/A", "2222"}, {"/dev/B", ""}});
  EXPECT_FALSE(result.moved);
  EXPECT_EQ(result.sources[0].name, "front");
  EXPECT_EQ(result.sources[0].serial, "2222");  // read, so outputs carry it
  EXPECT_EQ(result.sources[1].name, "rear");
  EXPECT_TRUE(result.notes.empty());
}

TEST(UnitIdentity, ASerialTwoUnitsShareBindsNeither) {
  const auto result = identify_units({bound("front", kFront, "2222"), bound("rear", kRear, "1111")},
                                     {{"/dev/A", "1111"}, {"/dev/B", "1111"}});
  EXPECT_FALSE(result.moved);
  EXPECT_EQ(result.sources[0].name, "front");
  EXPECT_EQ(result.sources[1].name, "rear");
  ASSERT_FALSE(result.notes.empty());
  EXPECT_EQ(
      result.notes[0],
      "2 units answer with serial 1111, so they cannot be told apart by it; each keeps the name given for its port");
}

TEST(UnitIdentity, TheModelStaysWithThePortItsSessionDecodes) {
  SourceInfo a = bound("front", kFront, "1111");
  a.model = Model::G6;
  SourceInfo b = bound("rear", kRear, "2222");
  b.model = Model::TG30;
  const auto result = identify_units({a, b}, {{"/dev/A", "2222"}, {"/dev/B", "1111"}});
  EXPECT_EQ(result.sources[0].name, "rear");
  EXPECT_EQ(result.sources[0].model, Model::G6);
}

}  // namespace
}  // namespace ydscope
