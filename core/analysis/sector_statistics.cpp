#include "core/analysis/sector_statistics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ydscope {

SectorAccumulator::SectorAccumulator(Sector sector, SectorStatisticsOptions options)
    : sector_(std::move(sector)), options_(options) {
  options_.angle_bins = std::max<std::size_t>(1, options_.angle_bins);
  clear();
}

void SectorAccumulator::clear() {
  laps_ = 0;
  points_ = 0;
  ranges_.clear();
  flat_distances_.clear();
  bin_points_.assign(options_.angle_bins, 0);
  bin_valid_.assign(options_.angle_bins, 0);
}

void SectorAccumulator::add(const Lap& lap) {
  ++laps_;
  const double width = sector_.width_deg();
  const double centre = sector_.centre_deg();
  const double bins_per_deg = static_cast<double>(options_.angle_bins) / width;
  for (const LapPoint& point : lap.points) {
    if (!sector_.contains(point)) continue;
    ++points_;
    const double offset = sector_.offset_deg(point.angle_deg);
    const auto bin = std::min(options_.angle_bins - 1, static_cast<std::size_t>(offset * bins_per_deg));
    ++bin_points_[bin];
    if (!is_valid_return(point)) continue;
    ++bin_valid_[bin];
    ranges_.push_back(point.range_mm);
    const double off_axis = (point.angle_deg - centre) * std::numbers::pi / 180.0;
    flat_distances_.push_back(static_cast<float>(point.range_mm * std::cos(off_axis)));
  }
}

SectorStatistics SectorAccumulator::statistics() const {
  SectorStatistics s;
  s.laps = laps_;
  s.points = points_;
  s.valid = ranges_.size();
  s.valid_share = points_ ? static_cast<double>(s.valid) / static_cast<double>(points_) : 0.0;
  std::vector<float> scratch = ranges_;
  s.range_mm = summarize_values(std::span<float>(scratch));
  scratch = flat_distances_;
  s.flat_distance_mm = summarize_values(std::span<float>(scratch));
  s.histogram = make_histogram(ranges_, s.range_mm.min, s.range_mm.max, options_.histogram_bins);
  s.angle_bin_deg = sector_.width_deg() / static_cast<double>(options_.angle_bins);
  s.valid_share_by_angle.resize(options_.angle_bins);
  for (std::size_t i = 0; i < options_.angle_bins; ++i)
    s.valid_share_by_angle[i] =
        bin_points_[i] ? static_cast<double>(bin_valid_[i]) / static_cast<double>(bin_points_[i]) : -1.0;
  return s;
}

}  // namespace ydscope
