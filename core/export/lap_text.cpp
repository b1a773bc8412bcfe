#include "core/export/lap_text.h"

#include "core/text/number_text.h"

namespace ydscope {

void append_point_fields(std::string& out, const LapPoint& point) {
  // 359.99996 rounds to "360": print the same direction as 0 to stay in [0, 360).
  const auto degrees = static_cast<double>(point.angle_deg);
  append_fixed(out, degrees >= 359.99995 ? 0.0 : degrees, 4);
  out.push_back(',');
  append_fixed(out, point.range_mm, 2);
  out.push_back(',');
  append_integer(out, static_cast<std::uint64_t>(point.flag));
}

void append_lap_csv_rows(std::string& out, std::uint64_t lap_index, double t_s, std::span<const LapPoint> points) {
  for (const LapPoint& point : points) {
    append_integer(out, lap_index);
    out.push_back(',');
    append_fixed(out, t_s, 6);
    out.push_back(',');
    append_point_fields(out, point);
    out.push_back('\n');
  }
}

}  // namespace ydscope
