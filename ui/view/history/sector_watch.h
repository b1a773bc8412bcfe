#pragma once
// A sector the user watches in the app (dragged on the view or typed in the Sectors panel): the
// statistics of the newest lap's points in it, and its mean range over the last laps, ready for
// ImGui's plot widgets. The sums are core/analysis's, the same the CLI's `check` uses.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/sector_statistics.h"
#include "ui/view/history/metric_history.h"

namespace ydscope::ui {

inline constexpr std::size_t kMaxWatchedSectors = 8;

class SectorWatch {
 public:
  static constexpr std::size_t kMeanLaps = 120;

  explicit SectorWatch(Sector sector);

  // The lap's statistics replace the previous lap's; its mean range joins the history.
  void add_lap(const Lap& lap);
  void clear();  // a new session: nothing measured yet

  const Sector& sector() const { return accumulator_.sector(); }
  const std::optional<SectorStatistics>& newest() const { return newest_; }
  const MetricHistory& mean_mm() const { return mean_mm_; }
  // The newest lap's histogram counts and valid share per angle bin (in %, 0 where the bin got no
  // points), as floats for PlotHistogram.
  const std::vector<float>& histogram() const { return histogram_; }
  const std::vector<float>& valid_pct_by_angle() const { return valid_pct_; }

  // What settings.ini keeps: "260:280" or, with a range band, "260:280 1500:2500".
  std::string spec() const { return sector_spec(sector()); }

 private:
  SectorAccumulator accumulator_;
  std::optional<SectorStatistics> newest_;
  MetricHistory mean_mm_{kMeanLaps};
  std::vector<float> histogram_;
  std::vector<float> valid_pct_;
};

// Adds `spec` ("260:280", or with a range band "260:280 1500:2500") to the watched sectors.
// Empty, or one sentence why not: a mistake in it, watched already, or too many.
std::string watch_sector(std::vector<SectorWatch>& sectors, const std::string& spec);

}  // namespace ydscope::ui
