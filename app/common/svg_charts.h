#pragma once
// Small inline-SVG pictures for the check report: plain markup (no scripts, no external files) in
// user units, so the report stays one self-contained file that any browser scales and prints.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/lap_timing.h"
#include "core/analysis/sector.h"
#include "core/analysis/value_summary.h"
#include "core/protocol/lap.h"

namespace ydscope {

// Each lap's rate against time, with the target as a line and the tolerance as a band; each gap
// is shaded and the line breaks there rather than running straight across it.
std::string svg_scan_rate_chart(std::span<const LapRateSample> series, std::span<const TimingGap> gaps,
                                double target_hz, double tolerance_pct);

// A value the unit is held to and how far from it it may be: drawn as a dashed line in a band.
struct TargetMark {
  double value = 0;
  double tolerance = 0;
  std::string label;  // "target 2400 mm ± 48 mm"
};

// Counts per bin of a histogram; `x_label` names the binned quantity ("range (mm)"). A target
// widens the axis to show its band when it lies outside the bins.
std::string svg_histogram_chart(const Histogram& histogram, std::string_view x_label,
                                const std::optional<TargetMark>& target = std::nullopt);

// Share of valid returns per angle bin (negative: no points fell in that bin), as bars, with the
// least share the sector must reach (0..1) as a line; bars below it are drawn red.
std::string svg_valid_share_chart(std::span<const double> share_by_angle, double from_deg, double bin_deg,
                                  double min_share);

// One lap seen from above: range rings, the points, and the sector as a shaded wedge.
std::string svg_polar_snapshot(const Lap& lap, const std::optional<Sector>& sector);

// Text made safe for HTML and SVG markup (&, <, >, " and ').
std::string markup_escaped(std::string_view text);

}  // namespace ydscope
