#pragma once
// Health problems in one short line each, worst first, for the view's status line and badge (the
// Health panel keeps the full table). Plain code, tested without a display.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/model_profile.h"
#include "ui/view/status/view_state.h"

namespace ydscope::ui {

struct HealthAlertInput {
  Model model = Model::G6;
  // The last health answer: G1 status bits (A5 92), or the G6/TG status 0/1/2 with its error code.
  std::optional<std::uint8_t> answer_status;
  std::uint16_t answer_error_code = 0;
  bool answer_is_bits = false;          // the answer came from A5 92 (bits) rather than A5 91 (status)
  std::optional<std::uint8_t> ct_bits;  // G1 CT health of the newest lap that carried it
  bool ct_trusted = true;               // that lap's CRC8 agreed
  std::uint64_t crc8_failures = 0;      // G1 laps whose LastCRC disagreed, this source
};

struct HealthAlert {
  Severity severity = Severity::Warning;
  std::string text;  // "health: Sensor, Encode", "error 0x0012 (A5 91 status 2)"
};

// Worst first; empty when the device says it is healthy (or has not been asked).
std::vector<HealthAlert> health_alerts(const HealthAlertInput& in);

// The worse of two severities.
Severity worst(Severity a, Severity b);

}  // namespace ydscope::ui
