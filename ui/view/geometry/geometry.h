#pragma once
// Small value types shared by the view code: 2D vectors in millimetres or pixels, 8-bit colours.
#include <cmath>
#include <cstdint>

namespace ydscope::ui {

struct Vec2 {
  float x = 0.0f;
  float y = 0.0f;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(Vec2 a, float s) { return {a.x * s, a.y * s}; }
inline float length(Vec2 v) { return std::hypot(v.x, v.y); }
inline float length_squared(Vec2 v) { return v.x * v.x + v.y * v.y; }

struct Rgba8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

// The view's world: x to the right of the screen, y up it, millimetres. A lidar is drawn in its
// laser frame the way ROS tools draw a REP-103 frame (view_frame.h): its forward (+x, the unit's
// 180 degrees) up, its left (+y, 90 degrees) to the left, so the unit's 0 degrees points down the
// screen and its clockwise angles (seen from above) sweep clockwise on screen.
inline Vec2 polar_to_world(float angle_deg, float range_mm) {
  constexpr float kDegToRad = 3.14159265358979f / 180.0f;
  const float a = angle_deg * kDegToRad;
  return {-range_mm * std::sin(a), -range_mm * std::cos(a)};
}

// Inverse of polar_to_world: angle in [0, 360).
inline float world_angle_deg(Vec2 world) {
  constexpr float kRadToDeg = 180.0f / 3.14159265358979f;
  float a = std::atan2(-world.x, -world.y) * kRadToDeg;
  if (a < 0.0f) a += 360.0f;
  if (a >= 360.0f) a -= 360.0f;
  return a;
}

}  // namespace ydscope::ui
