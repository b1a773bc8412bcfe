#pragma once
// The manuals' second-level angle correction. It depends only on the distance:
//   AngCorrect = atan(21.8 * (155.3 - D) / (155.3 * D)) in degrees, 0 when D == 0.
// The decoder looks it up per raw distance value in a table built once per decoder.
#include <cstdint>
#include <vector>

namespace ydscope {

double angle_correction_deg(double distance_mm);

// Wraps any angle into [0, 360).
double normalize_degrees(double degrees);

// Correction per raw distance value r (range = r * distance_scale), for r in [0, 65535].
class AngleCorrectionTable {
 public:
  // enabled false: all zero (a time-of-flight unit, read as the field reads it, needs none).
  AngleCorrectionTable(double distance_scale, bool enabled);
  float operator[](std::uint16_t raw_distance) const { return table_[raw_distance]; }

 private:
  std::vector<float> table_;
};

}  // namespace ydscope
