#include "ui/view/scene/pixel_merge.h"

#include <algorithm>
#include <cmath>

#include "ui/view/scene/colour_map.h"

namespace ydscope::ui {
namespace {

// Merging pays when it leaves at most this share of the sprites. It costs the CPU time of its own
// (a grouping a lap, a composite a frame): where it left 81 % of them (the virtual lidar's demo
// scene, which moves) that was about what llvmpipe saved (docs/performance.md).
constexpr float kWorthMerging = 0.75f;

}  // namespace

bool PixelMerger::same_points(const std::vector<PointVertex>& points, float cell_mm) const {
  if (cell_mm != cell_mm_ || points.size() * 2 != positions_.size()) return false;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].x != positions_[2 * i] || points[i].y != positions_[2 * i + 1]) return false;
  return true;
}

// Which slot each point goes to, slots made top first so each sits where its topmost point was.
bool PixelMerger::group(const std::vector<PointVertex>& points, float cell_mm) {
  float min_x = points[0].x, max_x = min_x, min_y = points[0].y, max_y = min_y;
  for (const PointVertex& p : points) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y);
    max_y = std::max(max_y, p.y);
  }
  // A cell is [k, k + 1) cell sizes from 0 on each axis, so -1 mm and 1 mm lie in two.
  const double first_x = std::floor(min_x / cell_mm), first_y = std::floor(min_y / cell_mm);
  const double columns = std::floor(max_x / cell_mm) - first_x + 1.0;
  const double rows = std::floor(max_y / cell_mm) - first_y + 1.0;
  if (!(columns * rows <= static_cast<double>(kMaxCells))) return false;  // NaN fails too
  const auto width = static_cast<std::size_t>(columns);
  const auto cells = width * static_cast<std::size_t>(rows);
  if (cells_.size() < cells) cells_.resize(cells, kNoSlot);
  slots_.clear();
  cell_of_slot_.clear();
  slot_of_.resize(points.size());
  positions_.resize(points.size() * 2);
  for (std::size_t i = points.size(); i-- > 0;) {
    const PointVertex& p = points[i];
    const auto column = static_cast<std::size_t>(std::floor(p.x / cell_mm) - first_x);
    const auto row = static_cast<std::size_t>(std::floor(p.y / cell_mm) - first_y);
    std::uint32_t& cell = cells_[row * width + column];
    if (cell == kNoSlot) {
      cell = static_cast<std::uint32_t>(slots_.size());
      cell_of_slot_.push_back(static_cast<std::uint32_t>(row * width + column));
      slots_.push_back({p.x, p.y});
    }
    slot_of_[i] = cell;
    positions_[2 * i] = p.x;
    positions_[2 * i + 1] = p.y;
  }
  for (const std::uint32_t cell : cell_of_slot_) cells_[cell] = kNoSlot;  // empty for the next grouping
  cell_mm_ = cell_mm;
  return true;
}

// Lays `p` under what `slot` holds so far, as the blend would have laid the stack bottom up.
void PixelMerger::lay_under(Slot& slot, const PointVertex& p) {
  const float alpha = p.colour.a * (1.0f / 255.0f);
  const float under = (1.0f - slot.a) * alpha;
  slot.r += under * p.colour.r;
  slot.g += under * p.colour.g;
  slot.b += under * p.colour.b;
  slot.a += under;
  slot.half_clear *= p.half_clear < 0.0f ? 1.0f - 0.5f * alpha : p.half_clear;
}

PointVertex PixelMerger::sprite_of(const Slot& slot) {
  const float inverse_alpha = slot.a > 0.0f ? 1.0f / (255.0f * slot.a) : 0.0f;  // and back to 0..1
  return {slot.x, slot.y,
          Rgba8{unit_to_byte(slot.r * inverse_alpha), unit_to_byte(slot.g * inverse_alpha),
                unit_to_byte(slot.b * inverse_alpha), unit_to_byte(slot.a)},
          slot.half_clear};
}

void PixelMerger::merge(std::vector<PointVertex>& points, float cell_mm) {
  if (points.size() < 2 || !(cell_mm > 0.0f && std::isfinite(cell_mm))) return;
  if (!same_points(points, cell_mm)) {
    if (!worth_merging_ && clouds_until_next_look_-- > 0) return;
    // Where few points share a pixel (a scene that moves from lap to lap), merging would cost the
    // CPU about what it saves the renderer: the points are drawn as they are.
    worth_merging_ = group(points, cell_mm) &&
                     static_cast<float>(slots_.size()) <= kWorthMerging * static_cast<float>(points.size());
    clouds_until_next_look_ = kCloudsBetweenLooks;
  }
  if (!worth_merging_) return;
  for (Slot& slot : slots_) slot = {slot.x, slot.y};
  for (std::size_t i = points.size(); i-- > 0;) lay_under(slots_[slot_of_[i]], points[i]);
  // Slots were made top first; drawn bottom first.
  points.clear();
  for (auto it = slots_.rbegin(); it != slots_.rend(); ++it) points.push_back(sprite_of(*it));
}

}  // namespace ydscope::ui
