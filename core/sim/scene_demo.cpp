#include "core/sim/scene_demo.h"

#include <algorithm>
#include <cmath>

#include "core/sim/scene_geometry.h"

namespace ydscope {

namespace {

using namespace scene_geometry;

constexpr int kPetals = 6;
constexpr double kFlowerTurnDegPerS = 12.0;
constexpr double kMoonOrbitMm = 2900;
constexpr double kMoonRadiusMm = 260;
constexpr double kMoonTurnDegPerS = -21.0;
constexpr int kStarSpikes = 9;
constexpr double kStarTurnDegPerS = 6.0;
constexpr double kBeamDegPerS = 45.0;
constexpr double kBeamWidthDeg = 24.0;

double wrap180(double degrees) {
  degrees = std::fmod(degrees + 180.0, 360.0);
  if (degrees < 0) degrees += 360.0;
  return degrees - 180.0;
}

}  // namespace

const DemoScene::Moons& DemoScene::moons_at(std::int64_t t_ns) const {
  const std::int64_t ms = t_ns / 1'000'000;
  if (moons_.ms == ms) return moons_;
  const double t = static_cast<double>(ms) * 1e-3;
  const double phase = 360.0 * hash_unit(seed_, 3, 4);
  for (int i = 0; i < kMoons; ++i) {
    const double a = (phase + 360.0 * i / kMoons + kMoonTurnDegPerS * t) * kPi / 180.0;
    const double orbit = kMoonOrbitMm + 250 * std::sin(2 * kPi * t / 5.0 + i);
    moons_.xy[2 * i] = orbit * std::cos(a);
    moons_.xy[2 * i + 1] = orbit * std::sin(a);
  }
  moons_.ms = ms;
  return moons_;
}

SceneReturn DemoScene::sample(double angle_deg, std::int64_t t_ns) const {
  const double t = static_cast<double>(t_ns) * 1e-9;
  const double phase = 360.0 * hash_unit(seed_, 3, 4);
  const auto angle_key = static_cast<std::int64_t>(std::llround(angle_deg * 1000.0));
  const double noise = 2.0 * hash_normal(seed_, angle_key, t_ns / 1000);
  SceneReturn out;

  // The flower: a rose curve r = R cos(k (theta - turn)), breathing; each petal is seen from the
  // origin as the single point where the ray leaves it.
  const double petal = std::cos(kPetals * (angle_deg - phase - kFlowerTurnDegPerS * t) * kPi / 180.0);
  if (petal > 0.18) {
    const double radius = 1700 + 350 * std::sin(2 * kPi * t / 7.0);
    out.range_mm = radius * petal + noise;
    if (petal > 0.97) out.flag = PointFlag::Specular;  // glinting petal tips
    return out;
  }

  // Moons orbiting the other way, visible between the petals.
  const Vec dir = direction(angle_deg);
  const Moons& moons = moons_at(t_ns);
  double nearest = kNoHit;
  for (int i = 0; i < kMoons; ++i)
    nearest = std::min(nearest, hit_circle({0, 0}, dir, {moons.xy[2 * i], moons.xy[2 * i + 1]}, kMoonRadiusMm));
  if (nearest != kNoHit) {
    out.range_mm = nearest + noise;
    return out;
  }

  // The star-shaped wall, counter-rotating, swept by the lighthouse beam.
  const double spike = std::cos(kStarSpikes * (angle_deg + kStarTurnDegPerS * t) * kPi / 180.0);
  out.range_mm = 4300 + 900 * spike * spike * spike + noise;
  if (std::abs(wrap180(angle_deg - kBeamDegPerS * t)) < kBeamWidthDeg / 2) out.flag = PointFlag::AmbientLight;
  return out;
}

}  // namespace ydscope
