#pragma once
// What the virtual lidar sees: a pure, deterministic function of (direction, time) -> range and
// interference flag. The same seed, angle and time always give the same answer.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include "core/protocol/lap.h"

namespace ydscope {

struct SceneReturn {
  double range_mm = 0.0;             // 0 = no return
  PointFlag flag = PointFlag::None;  // G1 interference flag (specular, ambient light)
};

class Scene {
 public:
  virtual ~Scene() = default;
  // angle_deg: direction in the lidar frame, [0, 360); t_ns: time since the device powered on.
  virtual SceneReturn sample(double angle_deg, std::int64_t t_ns) const = 0;
  virtual std::string_view name() const = 0;
  // The same scene seen from another spot of its floor (x_mm, y_mm in the scene's own coordinates,
  // where `sample` stands at 0, 0), angle_deg as `sample` reads it. Only scenes built of walls and
  // objects can be (room, booth); the demo's shapes are drawn round its origin: empty.
  virtual std::optional<SceneReturn> sample_from(double x_mm, double y_mm, double angle_deg, std::int64_t t_ns) const {
    (void)x_mm, (void)y_mm, (void)angle_deg, (void)t_ns;
    return std::nullopt;
  }
};

// A scene built of walls and objects on a floor (room, booth): it can be seen from any spot of it,
// and the lidar's own view is the one from the floor's origin. Each such scene says only what it
// holds (sample_from) and what it is called.
class FloorScene : public Scene {
 public:
  explicit FloorScene(std::uint64_t seed) : seed_(seed) {}
  SceneReturn sample(double angle_deg, std::int64_t t_ns) const final { return *sample_from(0, 0, angle_deg, t_ns); }
  std::optional<SceneReturn> sample_from(double x_mm, double y_mm, double angle_deg,
                                         std::int64_t t_ns) const override = 0;

 protected:
  std::uint64_t seed_;
};

// "room", "demo" or "booth" (case-sensitive); nullptr for any other name.
std::unique_ptr<Scene> make_scene(std::string_view name, std::uint64_t seed);
// "room, demo, booth" for messages and --help.
std::string_view scene_names();

// Deterministic noise shared by the scenes: a hash of (seed, a, b) mapped to [0, 1) or to an
// approximately normal value with unit deviation. Pure, so scenes stay pure.
double hash_unit(std::uint64_t seed, std::int64_t a, std::int64_t b);
double hash_normal(std::uint64_t seed, std::int64_t a, std::int64_t b);

}  // namespace ydscope
