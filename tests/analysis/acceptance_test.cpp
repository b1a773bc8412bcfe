// The acceptance criteria on observations built by hand: a good unit passes every criterion, and
// each single thing wrong with it fails exactly the criterion about that thing.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "core/analysis/acceptance.h"

namespace ydscope {
namespace {

CheckObservations good_g6() {
  CheckObservations o;
  o.profile = &profile_for(Model::G6);
  o.identity = {true, 13, "1.2", "0123456789012345"};
  o.health = {{"A5 91 before the run", false, "ok"}, {"A5 91 after the run", false, "ok"}};
  o.timing.laps = o.timing.normal_laps = 80;
  o.timing.mean_hz = 8.02;
  o.timing.min_hz = 7.98;
  o.timing.max_hz = 8.05;
  o.timing.jitter_pct = 0.3;
  o.timing.sample_rate_hz = 9003;
  o.timing.samples_per_lap = 1125;
  o.ranging_khz = 9;
  o.points = 90000;
  o.valid_points = 80000;
  SectorStatistics sector;
  sector.points = 1000;
  sector.valid = 990;
  sector.valid_share = 0.99;
  sector.flat_distance_mm = {990, 2405.0, 2404.0, 9.0, 2380.0, 2430.0};
  o.sector = sector;
  o.sector_name = "260:280";
  o.target_mm = 2400.0;
  return o;
}

std::set<std::string> failing(const CheckObservations& o, const AcceptanceLimits& limits) {
  std::set<std::string> ids;
  for (const CriterionResult& r : evaluate_acceptance(o, limits))
    if (r.verdict == Verdict::Fail) ids.insert(r.id);
  return ids;
}

const AcceptanceLimits kG6 = default_limits(profile_for(Model::G6));

TEST(Acceptance, AGoodUnitPassesEveryCriterion) {
  const auto results = evaluate_acceptance(good_g6(), kG6);
  ASSERT_EQ(results.size(), 11u);
  for (const auto& r : results) {
    EXPECT_EQ(r.verdict, Verdict::Pass) << r.id << ": " << r.measured << " against " << r.limit;
    EXPECT_FALSE(r.measured.empty()) << r.id;
    EXPECT_FALSE(r.limit.empty()) << r.id;
  }
  EXPECT_TRUE(all_passed(results));
  EXPECT_EQ(kG6.scan_hz_target, 8.0);
}

TEST(Acceptance, SectorAndRangeCriteriaOnlyWhenAsked) {
  CheckObservations o = good_g6();
  o.target_mm.reset();
  EXPECT_EQ(evaluate_acceptance(o, kG6).size(), 9u);
  o.sector.reset();
  EXPECT_EQ(evaluate_acceptance(o, kG6).size(), 8u);
}

struct OneThingWrong {
  const char* what;
  std::function<void(CheckObservations&)> spoil;
  const char* criterion;
};

TEST(Acceptance, EachFaultFailsExactlyItsCriterion) {
  const std::vector<OneThingWrong> cases{
      {"another model's code", [](CheckObservations& o) { o.identity.model_code = 19; }, "identity"},
      {"no serial", [](CheckObservations& o) { o.identity.serial.clear(); }, "identity"},
      {"no device info", [](CheckObservations& o) { o.identity.answered = false; }, "identity"},
      {"a health error after the run",
       [](CheckObservations& o) {
         o.health[1] = {"A5 91 after", true, "error"};
       },
       "health"},
      {"no health reading", [](CheckObservations& o) { o.health.clear(); }, "health"},
      {"rate 3 % high", [](CheckObservations& o) { o.timing.mean_hz = 8.24; }, "scan_rate"},
      {"rate 3 % low", [](CheckObservations& o) { o.timing.mean_hz = 7.76; }, "scan_rate"},
      {"jitter 2.5 %", [](CheckObservations& o) { o.timing.jitter_pct = 2.5; }, "scan_jitter"},
      {"8 kHz worth of samples", [](CheckObservations& o) { o.timing.sample_rate_hz = 8000; }, "sample_rate"},
      {"ranging not read", [](CheckObservations& o) { o.ranging_khz = 0; }, "sample_rate"},
      {"one checksum error", [](CheckObservations& o) { o.link.checksum_errors = 1; }, "link"},
      {"resync bytes", [](CheckObservations& o) { o.link.resync_bytes = 3; }, "link"},
      {"a CRC8 failure", [](CheckObservations& o) { o.link.crc8_failures = 1; }, "link"},
      {"a queue drop", [](CheckObservations& o) { o.link.queue_drops = 1; }, "link"},
      {"lost samples", [](CheckObservations& o) { o.link.lost_samples = 40; }, "link"},
      {"40 % valid", [](CheckObservations& o) { o.valid_points = 36000; }, "valid_returns"},
      {"a blocked sector",
       [](CheckObservations& o) {
         o.blocked_sectors = {{40, 75, 12.0}};
       },
       "blockage"},
      {"90 % valid in the sector", [](CheckObservations& o) { o.sector->valid = 900; }, "sector_valid"},
      {"60 mm long", [](CheckObservations& o) { o.sector->flat_distance_mm.mean = 2460; }, "range_bias"},
      {"30 mm noise", [](CheckObservations& o) { o.sector->flat_distance_mm.stddev = 30; }, "range_noise"},
  };
  for (const auto& c : cases) {
    CheckObservations o = good_g6();
    c.spoil(o);
    EXPECT_EQ(failing(o, kG6), std::set<std::string>{c.criterion}) << c.what;
  }
}

TEST(Acceptance, ABlockedSectorIsSaidInTheSentenceTheAppAndDiagnosticsUse) {
  CheckObservations o = good_g6();
  o.blocked_sectors = {{40, 75, 12.0}, {350, 10, 3.4}};
  for (const CriterionResult& r : evaluate_acceptance(o, kG6))
    if (r.id == "blockage") {
      EXPECT_EQ(r.title, "blocked sectors");
      EXPECT_EQ(r.measured, "blocked 40°–75° for 12 s; blocked 350°–10° for 3 s");
      EXPECT_EQ(r.verdict, Verdict::Fail);
      return;
    }
  ADD_FAILURE() << "no blockage criterion";
}

TEST(Acceptance, LimitsAreInclusiveAndOverridable) {
  CheckObservations o = good_g6();
  o.timing.mean_hz = 8.16;  // exactly +2 %
  EXPECT_TRUE(failing(o, kG6).empty());
  AcceptanceLimits strict = kG6;
  strict.scan_hz_tolerance_pct = 1.0;
  EXPECT_EQ(failing(o, strict), std::set<std::string>{"scan_rate"});
  AcceptanceLimits lenient = kG6;
  lenient.max_checksum_errors = 5;
  o = good_g6();
  o.link.checksum_errors = 5;
  EXPECT_TRUE(failing(o, lenient).empty());
  o.sector->flat_distance_mm.mean = 2460;
  lenient.bias_tolerance_mm = 100;
  EXPECT_TRUE(failing(o, lenient).empty());
}

TEST(Acceptance, RangeDefaultsScaleWithTheTargetDistance) {
  EXPECT_DOUBLE_EQ(default_bias_tolerance_mm(500), 20.0);
  EXPECT_DOUBLE_EQ(default_bias_tolerance_mm(5000), 100.0);
  EXPECT_DOUBLE_EQ(default_noise_max_mm(500), 10.0);
  EXPECT_DOUBLE_EQ(default_noise_max_mm(5000), 50.0);
}

TEST(Acceptance, G1ShowsItsCrc8CountOthersSayNotApplicable) {
  CheckObservations o = good_g6();
  const auto link_text = [](const CheckObservations& x) {
    for (const auto& r : evaluate_acceptance(x, kG6))
      if (r.id == "link") return r.measured;
    return std::string();
  };
  EXPECT_NE(link_text(o).find("CRC8 failures n/a"), std::string::npos);
  o.profile = &profile_for(Model::G1);
  o.link.crc8_failures = 2;
  EXPECT_NE(link_text(o).find("CRC8 failures 2"), std::string::npos);
}

TEST(Acceptance, EveryLimitSaysWhereItComesFrom) {
  for (const LimitSource& s : limit_sources()) {
    EXPECT_FALSE(s.value.empty()) << s.limit;
    EXPECT_FALSE(s.source.empty()) << s.limit;
    EXPECT_EQ(s.flag.substr(0, 2), "--") << s.limit;
  }
}

}  // namespace
}  // namespace ydscope
