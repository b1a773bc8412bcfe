#pragma once
// What is under the cursor (the nearest point of the newest lap within a pixel radius) and the ruler
// that measures between two clicked places.
#include <optional>
#include <span>

#include "core/protocol/lap.h"
#include "ui/view/geometry/view_transform.h"

namespace ydscope::ui {

struct PointHit {
  LapPoint point;
  Vec2 world;         // mm
  float distance_px;  // from the cursor
};

std::optional<PointHit> nearest_point(std::span<const LapPoint> points, const ViewTransform& view, Vec2 cursor_px,
                                      float max_distance_px);

// Click once for the first end, again for the second; a third click starts a new measurement.
class Ruler {
 public:
  void click(Vec2 world_mm);
  void clear() { first_.reset(), second_.reset(); }
  std::optional<Vec2> first() const { return first_; }
  std::optional<Vec2> second() const { return second_; }
  bool complete() const { return first_ && second_; }
  // Distance in mm between the ends; nullopt until both are set.
  std::optional<float> length_mm() const;

 private:
  std::optional<Vec2> first_;
  std::optional<Vec2> second_;
};

}  // namespace ydscope::ui
