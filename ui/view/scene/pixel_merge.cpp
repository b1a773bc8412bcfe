#include "ui/view/scene/pixel_merge.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "ui/view/scene/colour_map.h"

namespace ydscope::ui {
namespace {

// Merging pays when it leaves at most this share of the sprites. It costs the CPU time of its own
// (a grouping a lap, a composite a frame): where it left 81 % of them (the virtual lidar's demo
// scene, which moves) that was about what llvmpipe saved (docs/performance.md).
constexpr float kWorthMerging = 0.75f;

std::uint64_t cell_key(float x, float y, float cell_mm) {
  const auto cx = static_cast<std::int32_t>(std::floor(x / cell_mm));
  const auto cy = static_cast<std::int32_t>(std::floor(y / cell_mm));
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) << 32) | static_cast<std::uint32_t>(cy);
}

}  // namespace

bool PixelMerger::same_points(const std::vector<PointVertex>& points, float cell_mm) const {
  if (cell_mm != cell_mm_ || points.size() * 2 != positions_.size()) return false;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].x != positions_[2 * i] || points[i].y != positions_[2 * i + 1]) return false;
  return true;
}

// The slot of `key`'s cell, made (at x, y) if this grouping has not seen the cell yet.
std::uint32_t PixelMerger::slot_for(std::uint64_t key, float x, float y) {
  const std::size_t mask = table_.size() - 1;
  // Fibonacci hashing: the product's top bits, where every bit of both coordinates has a say. (Its
  // middle bits had left a row of cells along a wall to share a few buckets and probe on.)
  std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> table_shift_);
  for (;; i = (i + 1) & mask) {
    Cell& cell = table_[i];
    if (cell.round != round_) {
      cell = {key, static_cast<std::uint32_t>(slots_.size()), round_};
      slots_.push_back({x, y});
      return cell.slot;
    }
    if (cell.key == key) return cell.slot;
  }
}

// Which slot each point goes to, slots made top first so each sits where its topmost point was.
void PixelMerger::group(const std::vector<PointVertex>& points, float cell_mm) {
  const std::size_t size = std::bit_ceil(points.size() * 2);  // at most half full: short probes
  if (table_.size() < size) {
    table_.assign(size, {});
    table_shift_ = 64 - std::countr_zero(size);
    round_ = 0;
  }
  if (++round_ == 0) {  // wrapped: every old stamp could read as this grouping's
    std::fill(table_.begin(), table_.end(), Cell{});
    round_ = 1;
  }
  slots_.clear();
  slot_of_.resize(points.size());
  positions_.resize(points.size() * 2);
  for (std::size_t i = points.size(); i-- > 0;) {
    const PointVertex& p = points[i];
    slot_of_[i] = slot_for(cell_key(p.x, p.y, cell_mm), p.x, p.y);
    positions_[2 * i] = p.x;
    positions_[2 * i + 1] = p.y;
  }
  cell_mm_ = cell_mm;
}

// Lays `p` under what `slot` holds so far, as the blend would have laid the stack bottom up.
void PixelMerger::lay_under(Slot& slot, const PointVertex& p) {
  const float alpha = p.colour.a / 255.0f;
  const float under = (1.0f - slot.a) * alpha;
  slot.r += under * (p.colour.r / 255.0f);
  slot.g += under * (p.colour.g / 255.0f);
  slot.b += under * (p.colour.b / 255.0f);
  slot.a += under;
  slot.half_clear *= p.half_clear < 0.0f ? 1.0f - 0.5f * alpha : p.half_clear;
}

PointVertex PixelMerger::sprite_of(const Slot& slot) {
  const float inverse_alpha = slot.a > 0.0f ? 1.0f / slot.a : 0.0f;
  return {slot.x, slot.y,
          Rgba8{unit_to_byte(slot.r * inverse_alpha), unit_to_byte(slot.g * inverse_alpha),
                unit_to_byte(slot.b * inverse_alpha), unit_to_byte(slot.a)},
          slot.half_clear};
}

void PixelMerger::merge(std::vector<PointVertex>& points, float cell_mm) {
  if (points.size() < 2 || !(cell_mm > 0.0f && std::isfinite(cell_mm))) return;
  if (!same_points(points, cell_mm)) {
    if (!worth_merging_ && clouds_until_next_look_-- > 0) return;
    group(points, cell_mm);
    // Where few points share a pixel (a scene that moves from lap to lap), merging would cost the
    // CPU about what it saves the renderer: the points are drawn as they are.
    worth_merging_ = static_cast<float>(slots_.size()) <= kWorthMerging * static_cast<float>(points.size());
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
