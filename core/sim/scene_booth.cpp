#include "core/sim/scene_booth.h"

#include <array>
#include <cmath>

#include "core/sim/scene_geometry.h"

namespace ydscope {
namespace {

using namespace scene_geometry;

// The stand: back wall behind the lidar, side walls to the aisle. The aisle runs along y from the
// stand's front (x = 300) to the opposite stands (x = 3300), closed by the hall's end walls.
constexpr double kBack = -1500, kFront = 300, kHalfWidth = 1500, kOpposite = 3300, kHallEnd = 6000;
struct Segment {
  Vec a, b;
};
constexpr std::array<Segment, 5> kWalls{{
    {{kBack, -kHalfWidth}, {kBack, kHalfWidth}},
    {{kBack, kHalfWidth}, {kFront, kHalfWidth}},
    {{kBack, -kHalfWidth}, {kFront, -kHalfWidth}},
    {{kOpposite, -kHallEnd}, {kOpposite, kHallEnd}},
    {{kFront, kHallEnd}, {kOpposite, kHallEnd}},
}};
constexpr Segment kHallEndSouth{{kFront, -kHallEnd}, {kOpposite, -kHallEnd}};
constexpr Vec kKiosk{-700, 700};
constexpr double kKioskRadius = 300, kVisitorRadius = 220;
constexpr int kVisitors = 6;

// Where visitor `i` is at time t: a lane across the aisle, a direction, a speed, and a walk that
// wraps from one end of the hall to the other; some pause for a few seconds in front of the stand.
Vec visitor(std::uint64_t seed, int i, double t) {
  const double lane = kFront + 500 + 2000 * hash_unit(seed, i, 1);
  const double speed = 800 + 700 * hash_unit(seed, i, 2);  // mm/s
  const double dir = hash_unit(seed, i, 3) < 0.5 ? 1.0 : -1.0;
  const double length = 2 * kHallEnd;
  const double pause_s = hash_unit(seed, i, 4) < 0.4 ? 3.0 : 0.0;  // stops in front of the stand
  const double period = length / speed + pause_s;
  double s = std::fmod(t + period * hash_unit(seed, i, 5), period);
  // The pause happens at the middle of the walk, in front of the stand.
  const double half = 0.5 * length / speed;
  if (s > half) s = s < half + pause_s ? half : s - pause_s;
  return {lane, dir * (-kHallEnd + speed * s)};
}

}  // namespace

std::optional<SceneReturn> BoothScene::sample_from(double x_mm, double y_mm, double angle_deg,
                                                   std::int64_t t_ns) const {
  const double t = static_cast<double>(t_ns) * 1e-9;
  const Vec origin{x_mm, y_mm};
  const Vec d = direction(angle_deg);
  double best = hit_segment(origin, d, kHallEndSouth.a, kHallEndSouth.b);
  for (const Segment& w : kWalls) best = std::min(best, hit_segment(origin, d, w.a, w.b));
  best = std::min(best, hit_circle(origin, d, kKiosk, kKioskRadius));
  for (int i = 0; i < kVisitors; ++i)
    best = std::min(best, hit_circle(origin, d, visitor(seed_, i, t), kVisitorRadius));
  SceneReturn out;
  if (best == kNoHit) return out;
  const auto angle_key = static_cast<std::int64_t>(std::llround(angle_deg * 1000.0));
  const double sigma = 4.0 + 0.002 * best;
  out.range_mm = std::max(1.0, best + sigma * hash_normal(seed_, angle_key, t_ns / 1000));
  return out;
}

}  // namespace ydscope
