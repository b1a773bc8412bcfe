#pragma once
// Laps as text, written one way for every output that prints points: ydscope-cli's JSON lines
// and --format csv, and the app's CSV export of the laps on screen, so a file from either reads
// byte for byte the same.
#include <cstdint>
#include <span>
#include <string>

#include "core/protocol/lap.h"

namespace ydscope {

inline constexpr const char* kLapCsvHeader = "lap,t,angle_deg,range_mm,flag\n";

// A point's angle,range,flag: the angle with up to 4 decimals in [0, 360), the range in mm with
// up to 2, the flag as its number.
void append_point_fields(std::string& out, const LapPoint& point);

// One CSV row per point of a lap (kLapCsvHeader's columns): `t_s` is the lap's time, seconds from
// whatever origin the caller names.
void append_lap_csv_rows(std::string& out, std::uint64_t lap_index, double t_s, std::span<const LapPoint> points);

}  // namespace ydscope
