// The pure decisions behind the session: stepping toward a scan frequency, the failure sentences,
// choosing the model from a device-info code, and what a health answer means.
#include <gtest/gtest.h>

#include <optional>

#include "core/session/device_probe.h"

namespace ydscope {
namespace {

using namespace std::chrono_literals;

TEST(SessionProbe, ScanFrequencyStepsTakeWholeHertzFirstThenTenths) {
  EXPECT_EQ(next_scan_hz_step(8.0, 10.3), Command::ScanHzUpOne);
  EXPECT_EQ(next_scan_hz_step(9.0, 10.3), Command::ScanHzUpOne);
  EXPECT_EQ(next_scan_hz_step(10.0, 10.3), Command::ScanHzUpTenth);
  EXPECT_EQ(next_scan_hz_step(10.3, 10.3), std::nullopt);
  EXPECT_EQ(next_scan_hz_step(12.0, 7.5), Command::ScanHzDownOne);
  EXPECT_EQ(next_scan_hz_step(7.6, 7.5), Command::ScanHzDownTenth);
  EXPECT_EQ(next_scan_hz_step(7.53, 7.5), std::nullopt) << "within 0.05 Hz is reached";
}

TEST(SessionProbe, SteppingAlwaysEndsAtTheTarget) {
  for (int from = 500; from <= 1200; from += 7) {
    for (int to = 500; to <= 1200; to += 13) {
      double current = from / 100.0;
      int steps = 0;
      while (const auto step = next_scan_hz_step(current, to / 100.0)) {
        const double delta = *step == Command::ScanHzUpOne     ? 1.0
                             : *step == Command::ScanHzDownOne ? -1.0
                             : *step == Command::ScanHzUpTenth ? 0.1
                                                               : -0.1;
        current += delta;
        ASSERT_LT(++steps, 40) << from << " -> " << to;
      }
      EXPECT_NEAR(current, to / 100.0, 0.0501) << from << " -> " << to;
    }
  }
}

TEST(SessionProbe, NoReplySentencesSayWhatToTry) {
  const std::string silent = no_reply_sentence(Command::DeviceInfo, 1000ms, "/dev/ttyUSB0 at 230400 baud", 0);
  EXPECT_NE(silent.find("no reply to A5 90"), std::string::npos) << silent;
  EXPECT_NE(silent.find("within 1 s"), std::string::npos) << silent;
  EXPECT_NE(silent.find("/dev/ttyUSB0 at 230400 baud"), std::string::npos) << silent;
  EXPECT_NE(silent.find("wrong baud or model"), std::string::npos) << silent;
  const std::string noise = no_reply_sentence(Command::ScanHzGet, 250ms, "/dev/ttyUSB0 at 115200 baud", 37);
  EXPECT_NE(noise.find("37 bytes but no valid reply to A5 0D"), std::string::npos) << noise;
  EXPECT_NE(noise.find("0.25 s"), std::string::npos) << noise;
  EXPECT_NE(noise.find("--baud auto"), std::string::npos) << noise;
}

TEST(SessionProbe, TheModelComesFromTheCodeUnlessOneWasAskedFor) {
  std::string note;
  EXPECT_EQ(choose_profile(std::nullopt, 13, note), &profile_for(Model::G6));
  EXPECT_TRUE(note.empty());
  EXPECT_EQ(choose_profile(std::nullopt, 101, note), &profile_for(Model::TG30));
  EXPECT_EQ(choose_profile(std::nullopt, 77, note), nullptr);
  EXPECT_NE(note.find("77"), std::string::npos) << note;
  EXPECT_EQ(choose_profile(Model::G1, 13, note), &profile_for(Model::G1));
  EXPECT_NE(note.find("decoding as G1"), std::string::npos) << note;
}

TEST(SessionProbe, HealthAnswersInWords) {
  EXPECT_EQ(make_health_report(Command::HealthStatusBits, {0, 0}).summary, "ok");
  const HealthReport g1 = make_health_report(Command::HealthStatusBits, {kG1HealthSensor | kG1HealthData, 0});
  EXPECT_NE(g1.summary.find("abnormal"), std::string::npos) << g1.summary;
  EXPECT_NE(g1.summary.find(std::string(g1_health_bit_name(0))), std::string::npos) << g1.summary;
  EXPECT_NE(g1.summary.find(std::string(g1_health_bit_name(5))), std::string::npos) << g1.summary;
  EXPECT_EQ(make_health_report(Command::HealthStatusCode, {0, 0}).summary, "ok");
  const HealthReport g6 = make_health_report(Command::HealthStatusCode, {2, 0x12});
  EXPECT_NE(g6.summary.find("0x0012"), std::string::npos) << g6.summary;
  EXPECT_EQ(g6.status, 2);
}

}  // namespace
}  // namespace ydscope
