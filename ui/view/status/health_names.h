#pragma once
// What the health answers mean, in words, per model: G1's status bits (A5 92 and CT health) and
// the G6/TG status byte (A5 91). Taken from the manuals.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "core/protocol/model_profile.h"

namespace ydscope::ui {

struct HealthBitInfo {
  std::uint8_t bit;
  std::string_view name;
  std::string_view meaning;  // what it means when the bit is set
};

// G1: bits 0..5; 6 and 7 are reserved. Empty for models that report a status byte instead.
std::span<const HealthBitInfo> health_bits(Model model);
bool reports_health_bits(Model model);

struct HealthStatusInfo {
  std::string_view name;  // "normal", "warning", "error", "unknown"
  std::string_view meaning;
  bool is_problem;
};

// G6/TG A5 91 status byte: 0 normal, 1 warning, 2 error per the manuals.
HealthStatusInfo health_status_info(std::uint8_t status);

// "Sensor, Encode" or "all normal", for the health timeline.
std::string describe_health_bits(Model model, std::uint8_t bits);

}  // namespace ydscope::ui
