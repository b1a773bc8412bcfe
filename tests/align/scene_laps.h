#pragma once
// Laps straight from a virtual lidar's scene, without the device, its bytes or a port: what a
// lidar standing at `pose` in the scene measures, lap after lap, with the scene's own noise and
// its people walking. Fast enough for many poses and starts in one test.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/pose.h"
#include "core/protocol/lap.h"
#include "core/sim/posed_scene.h"
#include "core/sim/scene.h"

namespace ydscope::test {

inline std::vector<Lap> scene_laps(const std::string& scene_name, std::optional<Pose> pose, int laps,
                                   std::uint64_t seed = 1, int points_per_lap = 900) {
  std::unique_ptr<Scene> scene = make_scene(scene_name, seed);
  if (pose) scene = std::make_unique<PosedScene>(std::move(scene), *pose);
  constexpr std::int64_t kLapNs = 100'000'000;  // 10 Hz
  std::vector<Lap> out(static_cast<std::size_t>(laps));
  for (int l = 0; l < laps; ++l)
    for (int i = 0; i < points_per_lap; ++i) {
      const double angle = 360.0 * i / points_per_lap;
      const std::int64_t t = l * kLapNs + kLapNs * i / points_per_lap;
      const SceneReturn r = scene->sample(angle, t);
      out[static_cast<std::size_t>(l)].points.push_back(
          {static_cast<float>(angle), static_cast<float>(r.range_mm), r.flag});
    }
  return out;
}

}  // namespace ydscope::test
