#include "ui/view/history/sector_watch.h"

namespace ydscope::ui {

SectorWatch::SectorWatch(Sector sector) : accumulator_(std::move(sector)) {}

void SectorWatch::add_lap(const Lap& lap) {
  accumulator_.clear();
  accumulator_.add(lap);
  newest_ = accumulator_.statistics();
  if (newest_->range_mm.count > 0) mean_mm_.add(static_cast<float>(newest_->range_mm.mean));
  histogram_.assign(newest_->histogram.counts.begin(), newest_->histogram.counts.end());
  valid_pct_.clear();
  for (const double share : newest_->valid_share_by_angle)
    valid_pct_.push_back(share < 0 ? 0.0f : static_cast<float>(share * 100));
}

void SectorWatch::clear() {
  accumulator_.clear();
  newest_.reset();
  mean_mm_.clear();
  histogram_.clear();
  valid_pct_.clear();
}

std::string watch_sector(std::vector<SectorWatch>& sectors, const std::string& spec) {
  std::string error;
  const std::optional<Sector> sector = parse_sector_spec(spec, error);
  if (!sector) return error;
  const std::string canonical = sector_spec(*sector);
  for (const SectorWatch& w : sectors)
    if (w.spec() == canonical) return "sector " + canonical + " is watched already";
  if (sectors.size() >= kMaxWatchedSectors)
    return "at most " + std::to_string(kMaxWatchedSectors) + " sectors; remove one first";
  sectors.emplace_back(*sector);
  return {};
}

}  // namespace ydscope::ui
