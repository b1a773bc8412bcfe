#include "core/protocol/angle_correction.h"

#include <cmath>
#include <numbers>

namespace ydscope {

double angle_correction_deg(double distance_mm) {
  if (distance_mm == 0.0) return 0.0;
  constexpr double kBaseline = 155.3;
  constexpr double kOffset = 21.8;
  return std::atan(kOffset * (kBaseline - distance_mm) / (kBaseline * distance_mm)) * 180.0 / std::numbers::pi;
}

double normalize_degrees(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped < 0.0) wrapped += 360.0;
  if (wrapped >= 360.0) wrapped -= 360.0;  // -tiny + 360 rounds to 360
  return wrapped;
}

AngleCorrectionTable::AngleCorrectionTable(double distance_scale, bool enabled) : table_(65536, 0.0f) {
  if (!enabled) return;
  for (std::size_t raw = 0; raw < table_.size(); ++raw)
    table_[raw] = static_cast<float>(angle_correction_deg(static_cast<double>(raw) * distance_scale));
}

}  // namespace ydscope
