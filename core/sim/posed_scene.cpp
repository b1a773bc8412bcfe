#include "core/sim/posed_scene.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ydscope {
namespace {

constexpr double kProbeMm = 1000.0;  // a point this far along a ray gives its direction

}  // namespace

PosedScene::PosedScene(std::unique_ptr<Scene> base, const Pose& pose) : base_(std::move(base)), pose_(pose) {
  if (!base_->sample_from(0, 0, 0, 0))
    throw std::invalid_argument("the " + std::string(base_->name()) +
                                " scene is drawn round its origin and cannot be seen from another place; use room "
                                "or booth to place a virtual lidar");
  // A lidar at the origin sees device angle a along scene direction (cos a, sin a). Where its
  // common frame puts the 0 and 90 degree rays fixes the map from common to scene coordinates.
  const CommonPoint e0 = Pose{}.to_common(LapPoint{0.0f, static_cast<float>(kProbeMm), PointFlag::None});
  const CommonPoint e90 = Pose{}.to_common(LapPoint{90.0f, static_cast<float>(kProbeMm), PointFlag::None});
  // [e0 e90] (columns, in common) maps scene unit vectors to common; m is its inverse.
  const double a = e0.x_mm / kProbeMm, b = e90.x_mm / kProbeMm, c = e0.y_mm / kProbeMm, d = e90.y_mm / kProbeMm;
  const double det = a * d - b * c;
  m_[0][0] = d / det;
  m_[0][1] = -b / det;
  m_[1][0] = -c / det;
  m_[1][1] = a / det;
}

SceneReturn PosedScene::sample(double angle_deg, std::int64_t t_ns) const {
  const auto to_scene = [this](double x, double y) {
    return std::pair{m_[0][0] * x + m_[0][1] * y, m_[1][0] * x + m_[1][1] * y};
  };
  const CommonPoint at = pose_.to_common(LapPoint{static_cast<float>(angle_deg), 0.0f, PointFlag::None});
  const CommonPoint along =
      pose_.to_common(LapPoint{static_cast<float>(angle_deg), static_cast<float>(kProbeMm), PointFlag::None});
  const auto [x, y] = to_scene(at.x_mm, at.y_mm);
  const auto [dx, dy] = to_scene(along.x_mm - at.x_mm, along.y_mm - at.y_mm);
  double scene_angle = std::atan2(dy, dx) * 180.0 / std::numbers::pi;
  if (scene_angle < 0) scene_angle += 360.0;
  return base_->sample_from(x, y, scene_angle, t_ns).value_or(SceneReturn{});
}

}  // namespace ydscope
