#pragma once
// Ray casting for the scenes: a ray from the lidar (the origin) against segments and circles.
// Distances in mm; a miss is kNoHit. Small and header-only: the scenes are its only users.
#include <cmath>
#include <limits>

namespace ydscope::scene_geometry {

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.14159265358979323846;

struct Vec {
  double x = 0;
  double y = 0;
};

inline Vec direction(double angle_deg) {
  const double a = angle_deg * kPi / 180.0;
  return {std::cos(a), std::sin(a)};
}

// Distance along the ray origin + t*dir (|dir| = 1) to segment a-b, or kNoHit.
inline double hit_segment(Vec origin, Vec dir, Vec a, Vec b) {
  const Vec e{b.x - a.x, b.y - a.y};
  const double denom = dir.x * e.y - dir.y * e.x;
  if (std::abs(denom) < 1e-12) return kNoHit;
  const Vec w{a.x - origin.x, a.y - origin.y};
  const double t = (w.x * e.y - w.y * e.x) / denom;
  const double u = (w.x * dir.y - w.y * dir.x) / denom;
  if (t <= 1e-6 || u < 0.0 || u > 1.0) return kNoHit;
  return t;
}

// Distance along the ray to the circle (centre c, radius r) from outside, or kNoHit.
inline double hit_circle(Vec origin, Vec dir, Vec c, double r) {
  const Vec oc{origin.x - c.x, origin.y - c.y};
  const double b = oc.x * dir.x + oc.y * dir.y;
  const double cc = oc.x * oc.x + oc.y * oc.y - r * r;
  const double disc = b * b - cc;
  if (disc < 0.0) return kNoHit;
  const double t = -b - std::sqrt(disc);
  return t > 1e-6 ? t : kNoHit;
}

}  // namespace ydscope::scene_geometry
