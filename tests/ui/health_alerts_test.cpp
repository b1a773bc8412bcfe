// Health problems reach the view as short lines, worst first; a healthy device gives none.
#include <gtest/gtest.h>

#include "ui/view/status/health_alerts.h"

namespace ydscope::ui {
namespace {

TEST(HealthAlerts, HealthyDeviceHasNone) {
  HealthAlertInput in;
  in.model = Model::G6;
  in.answer_status = 0;
  EXPECT_TRUE(health_alerts(in).empty());
  in.model = Model::G1;
  in.answer_status = 0;
  in.answer_is_bits = true;
  in.ct_bits = 0;
  EXPECT_TRUE(health_alerts(in).empty());
  EXPECT_TRUE(health_alerts(HealthAlertInput{}).empty()) << "not asked yet is not a problem";
}

TEST(HealthAlerts, G6StatusOneIsAWarningTwoAnErrorWithTheCode) {
  HealthAlertInput in;
  in.model = Model::G6;
  in.answer_status = 1;
  in.answer_error_code = 0x0012;
  auto alerts = health_alerts(in);
  ASSERT_EQ(alerts.size(), 1u);
  EXPECT_EQ(alerts[0].severity, Severity::Warning);
  EXPECT_EQ(alerts[0].text, "health warning: status 1, error code 0x0012");
  in.answer_status = 2;
  alerts = health_alerts(in);
  ASSERT_EQ(alerts.size(), 1u);
  EXPECT_EQ(alerts[0].severity, Severity::Error);
  EXPECT_NE(alerts[0].text.find("0x0012"), std::string::npos);
}

TEST(HealthAlerts, G1BitsAreNamed) {
  HealthAlertInput in;
  in.model = Model::G1;
  in.answer_status = 0x03;
  in.answer_is_bits = true;
  const auto alerts = health_alerts(in);
  ASSERT_EQ(alerts.size(), 1u);
  EXPECT_EQ(alerts[0].severity, Severity::Error);
  EXPECT_EQ(alerts[0].text, "health (A5 92): Sensor, Encode");
}

TEST(HealthAlerts, UntrustedCtBitsWarnAndCrcFailuresCount) {
  HealthAlertInput in;
  in.model = Model::G1;
  in.ct_bits = 0x20;
  in.ct_trusted = false;
  in.crc8_failures = 3;
  const auto alerts = health_alerts(in);
  ASSERT_EQ(alerts.size(), 2u);
  EXPECT_EQ(alerts[0].severity, Severity::Warning);
  EXPECT_EQ(alerts[0].text, "health (CT, CRC8 failed): Data");
  EXPECT_EQ(alerts[1].text, "3 laps failed the CRC8 check: packets were lost");
}

TEST(HealthAlerts, WorstComesFirst) {
  HealthAlertInput in;
  in.model = Model::G1;
  in.crc8_failures = 1;
  in.ct_bits = 0x01;  // trusted: an error
  const auto alerts = health_alerts(in);
  ASSERT_EQ(alerts.size(), 2u);
  EXPECT_EQ(alerts[0].severity, Severity::Error);
  EXPECT_EQ(alerts[1].severity, Severity::Warning);
  EXPECT_EQ(worst(Severity::Info, Severity::Warning), Severity::Warning);
  EXPECT_EQ(worst(Severity::Error, Severity::Ok), Severity::Error);
}

}  // namespace
}  // namespace ydscope::ui
