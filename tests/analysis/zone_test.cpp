// Zones: the text form (what --zone and settings.ini take), and enter/leave events against the
// booth scene's visitors walking along the aisle in front of the virtual lidar. The truth is the
// scene itself, asked directly at each lap's time (no lidar, no decoder): whether any visitor
// stands in the zone then. The watch, fed the decoded laps, must say the same entries and exits
// within a few laps.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include "analysis/virtual_laps.h"
#include "core/analysis/zone_watch.h"
#include "core/sim/scene.h"

namespace ydscope {
namespace {

using namespace test;

Zone zone_of(const std::string& spec) {
  std::string error;
  const auto zone = parse_zone(spec, error);
  EXPECT_TRUE(zone) << error;
  return zone.value_or(Zone{});
}

TEST(ZoneSpec, ReadsSectorsAndPolygonsAndWritesThemBack) {
  const Zone front = zone_of("front:sector:330:30:500:3000");
  ASSERT_TRUE(front.sector);
  EXPECT_EQ(front.sector->width_deg(), 60.0);
  EXPECT_EQ(front.rule, ZoneRule::Enter);
  EXPECT_EQ(zone_spec(front), "front:sector:330:30:500:3000:enter");
  const Zone dock = zone_of("dock:polygon:0.5,-0.3/1.2,-0.3/1.2,0.3/0.5,0.3:empty");
  ASSERT_EQ(dock.polygon.size(), 4u);
  EXPECT_FLOAT_EQ(dock.polygon[1].x_mm, 1200.0f);
  EXPECT_EQ(dock.rule, ZoneRule::Empty);
  EXPECT_EQ(zone_spec(dock), "dock:polygon:0.5,-0.3/1.2,-0.3/1.2,0.3/0.5,0.3:empty");
  EXPECT_EQ(zone_spec(zone_of(zone_spec(dock))), zone_spec(dock));
  EXPECT_EQ(zone_of("side:sector:80:100:empty").rule, ZoneRule::Empty);
}

TEST(ZoneSpec, AMistakeIsOneSentenceNamingTheSyntax) {
  for (const char* bad : {"", "door", "door:circle:1,2", "do or:sector:1:2", "door:sector:10", "door:sector:10:10",
                          "door:sector:10:20:3000:100", "door:polygon:0,0/1,1", "door:polygon:0,0/1,1/2,2",
                          "door:polygon:0,0/1,x/2,0", "door:sector:10:20:leave"}) {
    std::string error;
    EXPECT_FALSE(parse_zone(bad, error)) << bad;
    EXPECT_NE(error.find("a zone is NAME:sector:"), std::string::npos) << bad << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST(ZoneWatch, EmptyRuleIsRaisedWhenNothingIsThere) {
  // The booth's kiosk table stands at 0.7 m forward, 0.7 m left of the lidar's robot frame.
  ZoneWatch watch({zone_of("kiosk:polygon:0.3,0.3/1.1,0.3/1.1,1.1/0.3,1.1:empty"),
                   zone_of("nothing:polygon:-0.2,-1.4/0.2,-1.4/0.2,-1.0/-0.2,-1.0:empty")});
  const VirtualRun run = scan_virtual_lidar(Model::G6, 2.0, {}, "booth");
  ASSERT_GT(run.laps.size(), 10u);
  for (const Lap& lap : run.laps) watch.add_lap(lap);
  EXPECT_TRUE(watch.states()[0].occupied) << "the kiosk is where the scene puts it";
  EXPECT_FALSE(watch.states()[0].raised);
  EXPECT_FALSE(watch.states()[1].occupied);
  EXPECT_TRUE(watch.states()[1].raised);
  EXPECT_NE(describe_zone(watch.zones()[1], watch.states()[1], watch.newest_ns()).find("it should not be"),
            std::string::npos);
}

struct Transition {
  bool entered;
  std::int64_t t_ns;
};

// The scene asked directly: is any return within the zone at time t? `in_zone` takes the scene's
// point in its own axes (x along the lidar's 0°, y along its 90°).
template <class InZone>
bool scene_has_visitor(const Scene& scene, std::int64_t t_ns, InZone in_zone) {
  int hits = 0;
  for (double a = 0; a < 360.0; a += 0.2) {
    const SceneReturn r = scene.sample(a, t_ns);
    if (r.range_mm <= 0) continue;
    const double rad = a * std::numbers::pi / 180.0;
    hits += in_zone(a, r.range_mm, r.range_mm * std::cos(rad), r.range_mm * std::sin(rad)) ? 1 : 0;
  }
  return hits >= 3;
}

struct VisitorCase {
  std::string name;
  std::string zone;
  std::function<bool(double a, double r, double x, double y)> truth;
};

class BoothVisitors : public ::testing::TestWithParam<VisitorCase> {};

TEST_P(BoothVisitors, EnterAndLeaveWhenTheSceneSaysTheyDo) {
  const VisitorCase& c = GetParam();
  const VirtualRun run = scan_virtual_lidar(Model::G6, 40.0, {}, "booth");
  ASSERT_GT(run.laps.size(), 300u);
  ZoneWatch watch({zone_of(c.zone)});
  std::vector<Transition> seen;
  for (const Lap& lap : run.laps)
    for (const ZoneEvent& e : watch.add_lap(lap)) seen.push_back({e.entered, e.t_ns});

  // The truth at each lap's middle, debounced as the watch is (clear after kZoneClearLaps laps).
  const std::unique_ptr<Scene> scene = make_scene("booth", 1);
  std::vector<Transition> truth;
  bool occupied = false;
  int quiet = 0;
  for (const Lap& lap : run.laps) {
    const std::int64_t t = (lap.first_rx_ns + lap.last_rx_ns) / 2;
    if (scene_has_visitor(*scene, t, c.truth)) {
      quiet = 0;
      if (!occupied) truth.push_back({true, lap.last_rx_ns});
      occupied = true;
    } else if (occupied && ++quiet >= kZoneClearLaps) {
      truth.push_back({false, lap.last_rx_ns});
      occupied = false;
    }
  }
  ASSERT_GE(truth.size(), 4u) << "too few visitors crossed the zone to judge";
  ASSERT_EQ(seen.size(), truth.size()) << "the watch saw another number of entries and exits";
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_EQ(seen[i].entered, truth[i].entered) << i;
    EXPECT_LE(std::llabs(seen[i].t_ns - truth[i].t_ns), 400 * kMs) << "event " << i << " off its visitor";
  }
}

// The aisle in front of the stand: scene x 500..3000 mm within 30° of the lidar's 0°; as a
// polygon in the robot's frame (REP-103: the unit's 0° points along -x, its 90° along +y).
INSTANTIATE_TEST_SUITE_P(Zones, BoothVisitors,
                         ::testing::Values(VisitorCase{"Sector", "aisle:sector:330:30:500:3000",
                                                       [](double a, double r, double, double) {
                                                         return (a >= 330.0 || a < 30.0) && r >= 500 && r <= 3000;
                                                       }},
                                           VisitorCase{"Polygon", "aisle:polygon:-0.5,-1/-3,-1/-3,1/-0.5,1",
                                                       [](double, double, double x, double y) {
                                                         return x >= 500 && x <= 3000 && y >= -1000 && y <= 1000;
                                                       }}),
                         [](const auto& test) { return test.param.name; });

}  // namespace
}  // namespace ydscope
