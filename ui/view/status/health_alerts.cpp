#include "ui/view/status/health_alerts.h"

#include <algorithm>
#include <cstdio>

#include "core/protocol/health_level.h"
#include "ui/view/status/health_names.h"

namespace ydscope::ui {

Severity worst(Severity a, Severity b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }

std::vector<HealthAlert> health_alerts(const HealthAlertInput& in) {
  std::vector<HealthAlert> alerts;
  const bool bits_model = reports_health_bits(in.model) || in.answer_is_bits;
  const HealthLevel answer_level = !in.answer_status ? HealthLevel::Ok
                                   : bits_model      ? health_bits_level(*in.answer_status)
                                                     : health_status_level(*in.answer_status, in.answer_error_code);
  if (answer_level != HealthLevel::Ok) {
    if (bits_model) {
      alerts.push_back({Severity::Error, "health (A5 92): " + describe_health_bits(in.model, *in.answer_status)});
    } else {
      const HealthStatusInfo info = health_status_info(*in.answer_status);
      char text[96];
      std::snprintf(text, sizeof text, "health %s: status %u, error code 0x%04X", std::string(info.name).c_str(),
                    static_cast<unsigned>(*in.answer_status), static_cast<unsigned>(in.answer_error_code));
      alerts.push_back({answer_level == HealthLevel::Warning ? Severity::Warning : Severity::Error, text});
    }
  }
  if (in.ct_bits && health_bits_level(*in.ct_bits) != HealthLevel::Ok) {
    // Untrusted CT bits may belong to another lap: worth a look, not an alarm.
    alerts.push_back({in.ct_trusted ? Severity::Error : Severity::Warning,
                      std::string(in.ct_trusted ? "health (CT): " : "health (CT, CRC8 failed): ") +
                          describe_health_bits(in.model, *in.ct_bits)});
  }
  if (in.crc8_failures > 0) {
    alerts.push_back({Severity::Warning, std::to_string(in.crc8_failures) + (in.crc8_failures == 1 ? " lap" : " laps") +
                                             " failed the CRC8 check: packets were lost"});
  }
  std::stable_sort(alerts.begin(), alerts.end(), [](const HealthAlert& a, const HealthAlert& b) {
    return static_cast<int>(a.severity) > static_cast<int>(b.severity);
  });
  return alerts;
}

}  // namespace ydscope::ui
