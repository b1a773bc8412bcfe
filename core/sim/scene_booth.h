#pragma once
// The "booth" scene: a trade-show stand 3 m wide and 1.8 m deep, the lidar on its counter facing
// a 3 m aisle, the opposite stands' wall beyond it and the hall's end walls to either side; a
// kiosk table in the stand, and visitors walking along the aisle both ways at 0.8 to 1.5 m/s (one
// now and then stops to look, then walks on). For motion highlighting with no hardware attached.
// Deterministic per seed, like every scene.
#include <cstdint>

#include "core/sim/scene.h"

namespace ydscope {

class BoothScene final : public FloorScene {
 public:
  using FloorScene::FloorScene;
  std::optional<SceneReturn> sample_from(double x_mm, double y_mm, double angle_deg, std::int64_t t_ns) const override;
  std::string_view name() const override { return "booth"; }
};

}  // namespace ydscope
