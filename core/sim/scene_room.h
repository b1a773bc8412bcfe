#pragma once
// The "room" scene: an 8 m x 6 m room with a pillar, a cabinet, a table's legs, two people walking,
// a mirror on one wall (specular-reflection points, flag 2: the range is the reflected path, as a
// real mirror ghost) and a sunlit window (no return through the glass, and ambient-light points,
// flag 3, at random ranges). Range noise grows with range. Deterministic per seed.
#include <cstdint>

#include "core/sim/scene.h"

namespace ydscope {

class RoomScene final : public FloorScene {
 public:
  using FloorScene::FloorScene;
  std::optional<SceneReturn> sample_from(double x_mm, double y_mm, double angle_deg, std::int64_t t_ns) const override;
  std::string_view name() const override { return "room"; }
};

}  // namespace ydscope
