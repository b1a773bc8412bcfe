#include "core/align/coarse_search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ydscope::align {
namespace {

// The reference cloud blurred onto a grid: each cell holds how close it is to a reference point,
// 1 on a point down to 0 three blurs away.
class Likelihood {
 public:
  Likelihood(std::span<const Point2> reference, double cell_mm, double blur_mm, double margin_mm) : cell_(cell_mm) {
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (const Point2& p : reference) {
      lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y), hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
    }
    x0_ = lo_x - margin_mm;
    y0_ = lo_y - margin_mm;
    width_ = static_cast<long>(std::ceil((hi_x - lo_x + 2 * margin_mm) / cell_)) + 1;
    height_ = static_cast<long>(std::ceil((hi_y - lo_y + 2 * margin_mm) / cell_)) + 1;
    value_.assign(static_cast<std::size_t>(width_ * height_), 0.0f);
    const long reach = static_cast<long>(std::ceil(3 * blur_mm / cell_));
    for (const Point2& p : reference) {
      const long cx = column(p.x), cy = row(p.y);
      for (long dy = -reach; dy <= reach; ++dy)
        for (long dx = -reach; dx <= reach; ++dx) {
          const long x = cx + dx, y = cy + dy;
          if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
          const double ex = x0_ + (static_cast<double>(x) + 0.5) * cell_ - p.x;
          const double ey = y0_ + (static_cast<double>(y) + 0.5) * cell_ - p.y;
          const auto v = static_cast<float>(std::exp(-(ex * ex + ey * ey) / (2 * blur_mm * blur_mm)));
          float& cell = value_[static_cast<std::size_t>(y * width_ + x)];
          cell = std::max(cell, v);
        }
    }
  }
  long column(double x) const { return static_cast<long>(std::floor((x - x0_) / cell_)); }
  long row(double y) const { return static_cast<long>(std::floor((y - y0_) / cell_)); }
  float at(long x, long y) const {
    return x < 0 || y < 0 || x >= width_ || y >= height_ ? 0.0f : value_[static_cast<std::size_t>(y * width_ + x)];
  }

 private:
  double cell_;
  double x0_ = 0, y0_ = 0;
  long width_ = 0, height_ = 0;
  std::vector<float> value_;
};

bool distinct(const Candidate& a, const Candidate& b) {
  const double turn = std::abs(std::remainder(a.motion.turn_rad - b.motion.turn_rad, 2 * std::numbers::pi));
  const double shift = std::hypot(a.motion.shift.x - b.motion.shift.x, a.motion.shift.y - b.motion.shift.y);
  return turn > 4.0 * std::numbers::pi / 180.0 || shift > 250.0;
}

}  // namespace

std::vector<Candidate> coarse_search(std::span<const Point2> reference, std::span<const Point2> moving, Point2 centre,
                                     const CoarseOptions& options) {
  std::vector<Candidate> found;
  if (reference.empty() || moving.empty()) return found;
  const Likelihood picture(reference, options.cell_mm, options.blur_mm, 0.0);
  std::vector<Point2> sample;
  const std::size_t stride = std::max<std::size_t>(1, moving.size() / options.max_points);
  for (std::size_t i = 0; i < moving.size(); i += stride) sample.push_back(moving[i]);

  const long shifts = static_cast<long>(std::round(options.window_shift_mm / options.cell_mm));
  const long turns = static_cast<long>(std::round(options.window_turn_deg / options.turn_step_deg));
  std::vector<std::pair<long, long>> cells(sample.size());
  std::vector<Candidate> best_per_turn;
  for (long k = -turns; k <= turns; ++k) {
    RigidMotion turned;
    turned.turn_rad = static_cast<double>(k) * options.turn_step_deg * std::numbers::pi / 180.0;
    turned.centre = centre;
    for (std::size_t i = 0; i < sample.size(); ++i) {
      const Point2 p = turned.apply(sample[i]);
      cells[i] = {picture.column(p.x), picture.row(p.y)};
    }
    // A shift of whole cells moves every point by the same cells: no rotation is redone.
    Candidate best;
    best.score = -1;
    for (long sy = -shifts; sy <= shifts; ++sy)
      for (long sx = -shifts; sx <= shifts; ++sx) {
        double score = 0;
        for (const auto& [x, y] : cells) score += picture.at(x + sx, y + sy);
        if (score > best.score) {
          best.score = score;
          best.motion = turned;
          best.motion.shift = {static_cast<double>(sx) * options.cell_mm, static_cast<double>(sy) * options.cell_mm};
        }
      }
    best.score /= static_cast<double>(sample.size());
    best_per_turn.push_back(best);
  }
  std::sort(best_per_turn.begin(), best_per_turn.end(),
            [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  for (const Candidate& c : best_per_turn) {
    if (found.size() >= options.keep) break;
    if (std::all_of(found.begin(), found.end(), [&](const Candidate& f) { return distinct(c, f); })) found.push_back(c);
  }
  return found;
}

}  // namespace ydscope::align
