#pragma once
// A scene seen by a virtual lidar that stands somewhere else in it: at `pose`, in the common frame
// of a lidar standing at the scene's origin unturned. Two virtual lidars, one at the origin and one
// posed, then see the same walls from two places, as two lidars on a robot do, and the pose that
// lines their clouds up is `pose` itself: what alignment (core/align) is measured against.
//
// The pose is read with core/frame's own transform (Pose::to_common), so it means here exactly
// what it means to the view, the recordings and the alignment, whatever that convention is.
#include <memory>
#include <string>

#include "core/frame/pose.h"
#include "core/sim/scene.h"

namespace ydscope {

class PosedScene final : public Scene {
 public:
  // Throws std::invalid_argument, one sentence, when `base` cannot be seen from elsewhere (demo).
  PosedScene(std::unique_ptr<Scene> base, const Pose& pose);
  SceneReturn sample(double angle_deg, std::int64_t t_ns) const override;
  std::string_view name() const override { return base_->name(); }

 private:
  std::unique_ptr<Scene> base_;
  Pose pose_;
  // The common frame of a lidar at the scene's origin, in scene coordinates: scene = m * common.
  double m_[2][2] = {{1, 0}, {0, 1}};
};

}  // namespace ydscope
