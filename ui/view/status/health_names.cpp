#include "ui/view/status/health_names.h"

#include <array>

namespace ydscope::ui {
namespace {

constexpr std::array<HealthBitInfo, 6> kG1Bits{{
    {0, "Sensor", "image sensor sampling signal abnormal"},
    {1, "Encode", "angle detection abnormal: cannot rotate or the angle jumps"},
    {2, "Power", "wireless power supply voltage weak (checked once at power-on)"},
    {3, "PD", "laser feedback abnormal: laser burned out or short-circuited (checked at power-on)"},
    {4, "LD", "laser drive current abnormal (checked once at power-on)"},
    {5, "Data", "no valid point in the lap: the window is blocked"},
}};

}  // namespace

std::span<const HealthBitInfo> health_bits(Model model) {
  if (model == Model::G1) return kG1Bits;
  return {};
}

bool reports_health_bits(Model model) { return model == Model::G1; }

HealthStatusInfo health_status_info(std::uint8_t status) {
  switch (status) {
    case 0: return {"normal", "the device is running normally", false};
    case 1: return {"warning", "the device reports a warning; see the error code", true};
    case 2: return {"error", "the device is running incorrectly; see the error code", true};
    default: return {"unknown", "a status value the manual does not list", true};
  }
}

std::string describe_health_bits(Model model, std::uint8_t bits) {
  if (bits == 0) return "all normal";
  std::string text;
  for (const HealthBitInfo& info : health_bits(model)) {
    if ((bits >> info.bit) & 1u) {
      if (!text.empty()) text += ", ";
      text += info.name;
    }
  }
  if (bits & 0xC0u) text += text.empty() ? "reserved bits" : ", reserved bits";
  return text;
}

}  // namespace ydscope::ui
