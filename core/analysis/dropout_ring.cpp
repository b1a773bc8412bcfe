#include "core/analysis/dropout_ring.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/text_format.h"
#include "core/protocol/angle_correction.h"

namespace ydscope {

namespace {

// Where the window pointed for this sample: a return's correction taken back off (no-returns
// carry none).
double window_angle_deg(const Lap& lap, const LapPoint& p) {
  const double corrected = p.angle_deg;
  return lap.angles_corrected && p.range_mm > 0.0f ? normalize_degrees(corrected - angle_correction_deg(p.range_mm))
                                                   : normalize_degrees(corrected);
}

std::size_t bin_of(double degrees) {
  return std::min(kDropoutBins - 1, static_cast<std::size_t>(degrees * kDropoutBins / 360.0));
}

}  // namespace

int BlockedSector::width_deg() const {
  const int w = ((to_deg - from_deg) % 360 + 360) % 360;
  return w == 0 ? 360 : w;
}

double BlockedSector::centre_deg() const { return normalize_degrees(from_deg + 0.5 * width_deg()); }

std::string describe_blocked_sector(const BlockedSector& s) {
  return format_text("blocked %d°–%d° for %.0f s", s.from_deg, s.to_deg, s.for_s);
}

std::string describe_blocked_sectors(const std::vector<BlockedSector>& sectors) {
  std::string text;
  for (const BlockedSector& s : sectors) text += (text.empty() ? "" : "; ") + describe_blocked_sector(s);
  return text;
}

DropoutRing::DropoutRing(DropoutOptions options) : options_(options) {}

void DropoutRing::clear() {
  laps_.clear();
  samples_.fill(0);
  misses_.fill(0);
  last_return_ns_.fill(0);
  first_ns_ = 0;
}

void DropoutRing::add_lap(const Lap& lap) {
  const std::int64_t t = lap.last_rx_ns;
  // A replay that went back, or laps again after an outage longer than the window: start again,
  // so an old sector's time does not run on across the gap.
  if (!laps_.empty() && (t < laps_.back().t_ns || t - laps_.back().t_ns > options_.window_ns)) clear();
  if (laps_.empty() && first_ns_ == 0) first_ns_ = t;
  LapBins& bins = laps_.emplace_back();
  bins.t_ns = t;
  for (const LapPoint& p : lap.points) {
    const std::size_t b = bin_of(window_angle_deg(lap, p));
    if (bins.samples[b] == UINT16_MAX) continue;
    ++bins.samples[b];
    if (p.range_mm > 0.0f)
      last_return_ns_[b] = t;
    else
      ++bins.misses[b];
  }
  for (std::size_t b = 0; b < kDropoutBins; ++b) {
    samples_[b] += bins.samples[b];
    misses_[b] += bins.misses[b];
  }
  while (!laps_.empty() && laps_.front().t_ns < t - options_.window_ns) {
    for (std::size_t b = 0; b < kDropoutBins; ++b) {
      samples_[b] -= laps_.front().samples[b];
      misses_[b] -= laps_.front().misses[b];
    }
    laps_.pop_front();
  }
}

std::array<float, kDropoutBins> DropoutRing::no_return_share() const {
  std::array<float, kDropoutBins> share{};
  for (std::size_t b = 0; b < kDropoutBins; ++b)
    share[b] = samples_[b] ? static_cast<float>(misses_[b]) / static_cast<float>(samples_[b]) : -1.0f;
  return share;
}

std::vector<BlockedSector> DropoutRing::blocked() const {
  std::vector<BlockedSector> out;
  if (laps_.empty() || first_ns_ == 0 || laps_.back().t_ns - first_ns_ < options_.min_span_ns) return out;
  std::array<bool, kDropoutBins> empty{};
  for (std::size_t b = 0; b < kDropoutBins; ++b)
    empty[b] = samples_[b] > 0 && misses_[b] >= options_.blocked_share * samples_[b];
  // Start the walk at a degree that sees returns, so a sector across 0° comes out whole.
  const auto seeing = std::find(empty.begin(), empty.end(), false);
  if (seeing == empty.end()) return out;  // nothing anywhere: not a blockage in one place
  const std::size_t start = static_cast<std::size_t>(seeing - empty.begin());
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // first bin, bins
  for (std::size_t i = 0; i < kDropoutBins; ++i) {
    const std::size_t b = (start + i) % kDropoutBins;
    if (!empty[b]) continue;
    if (!runs.empty() && (runs.back().first + runs.back().second) % kDropoutBins == b)
      ++runs.back().second;
    else
      runs.push_back({b, 1});
  }
  const double bin_deg = 360.0 / kDropoutBins;
  std::uint64_t other_samples = 0, other_returns = 0;
  std::array<bool, kDropoutBins> in_sector{};
  for (const auto& [first, count] : runs) {
    if (static_cast<double>(count) * bin_deg < options_.min_width_deg) continue;
    for (std::size_t i = 0; i < count; ++i) in_sector[(first + i) % kDropoutBins] = true;
  }
  for (std::size_t b = 0; b < kDropoutBins; ++b)
    if (!in_sector[b]) {
      other_samples += samples_[b];
      other_returns += samples_[b] - misses_[b];
    }
  if (other_samples == 0 ||
      static_cast<double>(other_returns) < options_.min_others_return_share * static_cast<double>(other_samples))
    return out;
  const std::int64_t now = laps_.back().t_ns;
  for (const auto& [first, count] : runs) {
    if (static_cast<double>(count) * bin_deg < options_.min_width_deg) continue;
    std::int64_t last_return = first_ns_;
    for (std::size_t i = 0; i < count; ++i)
      last_return = std::max(last_return, last_return_ns_[(first + i) % kDropoutBins]);
    BlockedSector s;
    s.from_deg = static_cast<int>(std::lround(static_cast<double>(first) * bin_deg)) % 360;
    s.to_deg = static_cast<int>(std::lround(static_cast<double>(first + count) * bin_deg)) % 360;
    s.for_s = static_cast<double>(now - last_return) * 1e-9;
    out.push_back(s);
  }
  std::sort(out.begin(), out.end(),
            [](const BlockedSector& a, const BlockedSector& b) { return a.from_deg < b.from_deg; });
  return out;
}

}  // namespace ydscope
