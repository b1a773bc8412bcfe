#include "app/common/svg_charts.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/text_format.h"
#include "core/text/json_string.h"

namespace ydscope {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kInk = "#1f2933";
constexpr const char* kGrid = "#d9dee3";
constexpr const char* kData = "#1565c0";
constexpr const char* kTarget = "#2e7d32";
constexpr const char* kGap = "#c62828";

// A step of 1, 2 or 5 times a power of ten giving about `wanted` intervals over span.
double nice_step(double span, int wanted) {
  if (!(span > 0)) return 1;
  const double raw = span / wanted;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (raw <= m * power) return m * power;
  return 10 * power;
}

// Enough decimals to tell ticks `step` apart.
int decimals_for(double step) { return step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9)); }

// A chart area inside a picture, mapping data to user units (y grows upwards in the data).
struct PlotFrame {
  double width = 640, height = 260;
  double left = 64, right = 16, top = 16, bottom = 44;
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;

  double sx(double x) const { return left + (x - x_lo) / (x_hi - x_lo) * (width - left - right); }
  double sy(double y) const { return height - bottom - (y - y_lo) / (y_hi - y_lo) * (height - top - bottom); }

  std::string open(std::string_view title) const {
    return format_text(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 %.0f %.0f" role="img" )"
                       R"(font-family="sans-serif" font-size="12"><title>%s</title>)",
                       width, height, markup_escaped(title).c_str());
  }

  // Grid lines, tick labels and axis names.
  std::string axes(std::string_view x_label, std::string_view y_label) const {
    std::string svg;
    const double x_step = nice_step(x_hi - x_lo, 6), y_step = nice_step(y_hi - y_lo, 5);
    for (double x = std::ceil(x_lo / x_step) * x_step; x <= x_hi + x_step * 1e-6; x += x_step)
      svg += format_text(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s"/>)"
                         R"(<text x="%.1f" y="%.1f" text-anchor="middle" fill="%s">%.*f</text>)",
                         sx(x), top, sx(x), height - bottom, kGrid, sx(x), height - bottom + 16, kInk,
                         decimals_for(x_step), x);
    for (double y = std::ceil(y_lo / y_step) * y_step; y <= y_hi + y_step * 1e-6; y += y_step)
      svg += format_text(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s"/>)"
                         R"(<text x="%.1f" y="%.1f" text-anchor="end" fill="%s">%.*f</text>)",
                         left, sy(y), width - right, sy(y), kGrid, left - 6, sy(y) + 4, kInk, decimals_for(y_step), y);
    svg += format_text(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="%s"/>)", left, top,
                       width - left - right, height - top - bottom, kInk);
    svg += format_text(R"(<text x="%.1f" y="%.1f" text-anchor="middle" fill="%s">%s</text>)",
                       (left + width - right) / 2, height - 8, kInk, markup_escaped(x_label).c_str());
    svg += format_text(R"~(<text transform="translate(14 %.1f) rotate(-90)" text-anchor="middle" fill="%s">%s</text>)~",
                       (top + height - bottom) / 2, kInk, markup_escaped(y_label).c_str());
    return svg;
  }
};

// The band a value must stay in, shaded in the target's colour: across x (lo..hi on the x axis)
// or across y.
std::string target_band(const PlotFrame& f, double lo, double hi, bool along_x) {
  const double x0 = along_x ? f.sx(lo) : f.left, x1 = along_x ? f.sx(hi) : f.width - f.right;
  const double y0 = along_x ? f.top : f.sy(hi), y1 = along_x ? f.height - f.bottom : f.sy(lo);
  return format_text(R"(<rect class="tolerance" x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s" )"
                     R"(fill-opacity="0.12"/>)",
                     x0, y0, std::max(x1 - x0, 1.0), std::max(y1 - y0, 1.0), kTarget);
}

// The target's words, top right inside the plot.
std::string target_label(const PlotFrame& f, std::string_view text) {
  return format_text(R"(<text x="%.1f" y="%.1f" text-anchor="end" fill="%s">%s</text>)", f.width - f.right - 6,
                     f.top + 14, kTarget, markup_escaped(text).c_str());
}

std::string empty_chart(std::string_view title, std::string_view sentence) {
  PlotFrame frame;
  frame.height = 80;
  return frame.open(title) + format_text(R"(<text x="%.0f" y="44" text-anchor="middle" fill="%s">%s</text></svg>)",
                                         frame.width / 2, kInk, markup_escaped(sentence).c_str());
}

}  // namespace

std::string markup_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {  // keep valid UTF-8, replace stray bytes (a device's serial may hold any)
      const std::size_t length = utf8_sequence_length(text, i);
      out += length ? text.substr(i, length) : std::string_view("\uFFFD");
      i += length ? length : 1;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += (u < 0x20 && c != '\n' && c != '\t') || u == 0x7F ? "\uFFFD" : std::string(1, c);
    }
    ++i;
  }
  return out;
}

std::string svg_scan_rate_chart(std::span<const LapRateSample> series, std::span<const TimingGap> gaps,
                                double target_hz, double tolerance_pct) {
  constexpr const char* kTitle = "Scan rate of each lap over the run";
  if (series.empty()) return empty_chart(kTitle, "no complete lap was measured");
  const double band = target_hz * tolerance_pct / 100;
  PlotFrame f;
  f.x_hi = std::max(series.back().t_s, 1.0);
  for (const TimingGap& gap : gaps) f.x_hi = std::max(f.x_hi, gap.to_s);
  f.y_lo = target_hz - band, f.y_hi = target_hz + band;
  for (const LapRateSample& s : series) f.y_lo = std::min(f.y_lo, s.hz), f.y_hi = std::max(f.y_hi, s.hz);
  const double pad = std::max((f.y_hi - f.y_lo) * 0.15, 0.05);
  f.y_lo -= pad, f.y_hi += pad;

  std::string svg = f.open(kTitle);
  svg += target_band(f, target_hz - band, target_hz + band, false);
  svg += f.axes("time (s)", "scan rate (Hz)");
  svg += format_text(
      R"(<line class="target" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-dasharray="6 4"/>)", f.left,
      f.sy(target_hz), f.width - f.right, f.sy(target_hz), kTarget);
  for (const TimingGap& gap : gaps) {
    const double x0 = f.sx(gap.from_s), x1 = f.sx(gap.to_s);
    svg +=
        format_text(R"(<rect class="gap" x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s" fill-opacity="0.25">)"
                    R"(<title>%s</title></rect>)",
                    x0, f.top, std::max(x1 - x0, 2.0), f.sy(f.y_lo) - f.top, kGap,
                    markup_escaped(describe_timing_gap(gap)).c_str());
  }
  // One polyline per stretch between gaps.
  std::size_t next_gap = 0;
  bool open = false;
  for (const LapRateSample& s : series) {
    const std::size_t gaps_before = next_gap;
    while (next_gap < gaps.size() && gaps[next_gap].from_s < s.t_s) ++next_gap;
    if (open && next_gap != gaps_before) {
      svg += R"("/>)";
      open = false;
    }
    if (!open) svg += format_text(R"(<polyline fill="none" stroke="%s" stroke-width="1.5" points=")", kData);
    open = true;
    svg += format_text("%.1f,%.1f ", f.sx(s.t_s), f.sy(s.hz));
  }
  if (open) svg += R"("/>)";
  svg += target_label(f, format_text("target %.2f Hz ± %.1f %%", target_hz, tolerance_pct));
  return svg + "</svg>";
}

std::string svg_histogram_chart(const Histogram& histogram, std::string_view x_label,
                                const std::optional<TargetMark>& target) {
  constexpr const char* kTitle = "Histogram of the sector's ranges";
  std::uint32_t most = 0;
  for (const std::uint32_t c : histogram.counts) most = std::max(most, c);
  if (most == 0) return empty_chart(kTitle, "no valid return fell in the sector");
  PlotFrame f;
  f.x_lo = histogram.lo, f.x_hi = histogram.hi;
  if (target) {
    // The band's edges inside the axis, so the eye sees where the limit runs out.
    const double margin = std::max(target->tolerance * 1.25, (f.x_hi - f.x_lo) * 0.02);
    f.x_lo = std::min(f.x_lo, target->value - margin), f.x_hi = std::max(f.x_hi, target->value + margin);
  }
  f.y_hi = most * 1.1;
  std::string svg = f.open(kTitle);
  if (target) svg += target_band(f, target->value - target->tolerance, target->value + target->tolerance, true);
  svg += f.axes(x_label, "points");
  const double w = histogram.bin_width();
  for (std::size_t i = 0; i < histogram.counts.size(); ++i) {
    const double x0 = histogram.lo + w * static_cast<double>(i);
    svg += format_text(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"/>)", f.sx(x0),
                       f.sy(histogram.counts[i]), std::max(f.sx(x0 + w) - f.sx(x0) - 1, 0.5),
                       f.sy(0) - f.sy(histogram.counts[i]), kData);
  }
  if (target) {
    svg += format_text(
        R"(<line class="target" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-dasharray="6 4"/>)",
        f.sx(target->value), f.top, f.sx(target->value), f.height - f.bottom, kTarget);
    svg += target_label(f, target->label);
  }
  return svg + "</svg>";
}

std::string svg_valid_share_chart(std::span<const double> share_by_angle, double from_deg, double bin_deg,
                                  double min_share) {
  constexpr const char* kTitle = "Share of valid returns per angle in the sector";
  if (share_by_angle.empty()) return empty_chart(kTitle, "no sector was measured");
  PlotFrame f;
  f.x_lo = 0, f.x_hi = bin_deg * static_cast<double>(share_by_angle.size());
  f.y_hi = 110;  // room above 100 % for the limit's words
  std::string svg = f.open(kTitle);
  svg += target_band(f, min_share * 100, 100, false);
  svg += f.axes(format_text("degrees past %.1f°", from_deg), "valid (%)");
  for (std::size_t i = 0; i < share_by_angle.size(); ++i) {
    const double x0 = bin_deg * static_cast<double>(i), share = share_by_angle[i];
    if (share < 0) continue;  // no points there: no bar, rather than a misleading 0 %
    svg += format_text(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"/>)", f.sx(x0), f.sy(share * 100),
                       std::max(f.sx(x0 + bin_deg) - f.sx(x0) - 1, 0.5), f.sy(0) - f.sy(share * 100),
                       share >= min_share ? kTarget : kGap);
  }
  svg += format_text(
      R"(<line class="target" x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-dasharray="6 4"/>)", f.left,
      f.sy(min_share * 100), f.width - f.right, f.sy(min_share * 100), kInk);
  svg += target_label(f, format_text("limit: at least %.1f %%", min_share * 100));
  return svg + "</svg>";
}

std::string svg_polar_snapshot(const Lap& lap, const std::optional<Sector>& sector) {
  constexpr double kSize = 480, kCentre = kSize / 2, kRadius = kSize / 2 - 28;
  std::string svg = format_text(R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 %.0f %.0f" role="img" )"
                                R"(font-family="sans-serif" font-size="11"><title>The last lap from above</title>)",
                                kSize, kSize);
  float far = 0;
  for (const LapPoint& p : lap.points) far = std::max(far, p.range_mm);
  if (lap.points.empty() || far <= 0)
    return svg +
           format_text(R"(<text x="%.0f" y="%.0f" text-anchor="middle" fill="%s">no lap was measured</text></svg>)",
                       kCentre, kCentre, kInk);
  const double step_mm = nice_step(far, 4), outer_mm = std::ceil(far / step_mm) * step_mm;
  const double scale = kRadius / outer_mm;
  // Angles run clockwise from straight ahead (up), as the lidar counts them.
  const auto at = [&](double angle_deg, double r_mm, double& x, double& y) {
    const double a = angle_deg * kPi / 180;
    x = kCentre + std::sin(a) * r_mm * scale;
    y = kCentre - std::cos(a) * r_mm * scale;
  };
  if (sector) {
    double x0, y0, x1, y1;
    at(sector->from_deg, outer_mm, x0, y0);
    at(sector->from_deg + sector->width_deg(), outer_mm, x1, y1);
    svg += format_text(R"(<path d="M%.1f %.1f L%.1f %.1f A%.1f %.1f 0 %d 1 %.1f %.1f Z" fill="#f9a825" )"
                       R"(fill-opacity="0.25" stroke="#f9a825"/>)",
                       kCentre, kCentre, x0, y0, kRadius, kRadius, sector->width_deg() > 180 ? 1 : 0, x1, y1);
  }
  for (double r = step_mm; r <= outer_mm + step_mm * 1e-6; r += step_mm)
    svg += format_text(R"(<circle cx="%.0f" cy="%.0f" r="%.1f" fill="none" stroke="%s"/>)"
                       R"(<text x="%.1f" y="%.1f" fill="%s">%.*f m</text>)",
                       kCentre, kCentre, r * scale, kGrid, kCentre + 3, kCentre - r * scale - 3, kInk,
                       decimals_for(step_mm / 1000), r / 1000);
  svg += format_text(R"(<line x1="%.0f" y1="%.0f" x2="%.0f" y2="%.1f" stroke="%s" stroke-dasharray="3 3"/>)", kCentre,
                     kCentre, kCentre, kCentre - kRadius, kGrid);
  svg += format_text(R"(<text x="%.0f" y="14" text-anchor="middle" fill="%s">0°</text>)", kCentre, kInk);
  // One short round-capped segment per point keeps thousands of points to one compact element.
  svg += format_text(R"(<path fill="none" stroke="%s" stroke-width="3" stroke-linecap="round" d=")", kData);
  for (const LapPoint& p : lap.points) {
    if (p.range_mm <= 0) continue;
    double x, y;
    at(p.angle_deg, p.range_mm, x, y);
    svg += format_text("M%.1f %.1fh0", x, y);
  }
  svg += R"("/>)";
  svg += format_text(R"(<circle cx="%.0f" cy="%.0f" r="4" fill="%s"/>)", kCentre, kCentre, kInk);
  return svg + "</svg>";
}

}  // namespace ydscope
