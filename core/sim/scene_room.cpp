#include "core/sim/scene_room.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "core/sim/scene_geometry.h"

namespace ydscope {

namespace {

using namespace scene_geometry;

enum class Surface { None, Matte, Mirror, Window };

struct Hit {
  double t = kNoHit;
  Surface surface = Surface::None;
};

struct RoomWall {
  Vec a;
  Vec b;
  Surface surface;
};

// Room 8 m x 6 m; the lidar stands at the origin, off-centre. Right wall holds the mirror, top wall
// the window, so both are split around them.
constexpr double kLeft = -3200, kRight = 4800, kBottom = -2400, kTop = 3600;
constexpr std::array<RoomWall, 12> kRoomWalls{{
    {{kLeft, kBottom}, {kRight, kBottom}, Surface::Matte},
    {{kRight, kBottom}, {kRight, -1400}, Surface::Matte},
    {{kRight, -1400}, {kRight, 400}, Surface::Mirror},
    {{kRight, 400}, {kRight, kTop}, Surface::Matte},
    {{kRight, kTop}, {800, kTop}, Surface::Matte},
    {{800, kTop}, {-1800, kTop}, Surface::Window},
    {{-1800, kTop}, {kLeft, kTop}, Surface::Matte},
    {{kLeft, kTop}, {kLeft, kBottom}, Surface::Matte},
    // A cabinet against the bottom-left wall.
    {{-3000, -1800}, {-1900, -1800}, Surface::Matte},
    {{-1900, -1800}, {-1900, -2300}, Surface::Matte},
    {{-3000, -1800}, {-3000, -2300}, Surface::Matte},
    {{-1900, -2300}, {-3000, -2300}, Surface::Matte},
}};

struct Circle {
  Vec c;
  double r;
};

// A pillar and the four legs of a table.
constexpr std::array<Circle, 5> kFixedCircles{{
    {{3400, 2400}, 250},
    {{1000, -1500}, 25},
    {{1900, -1500}, 25},
    {{1000, -900}, 25},
    {{1900, -900}, 25},
}};

constexpr double kPersonRadius = 220;

Hit nearest(Vec origin, Vec dir, std::span<const Circle> people) {
  Hit best;
  for (const auto& s : kRoomWalls) {
    const double t = hit_segment(origin, dir, s.a, s.b);
    if (t < best.t) best = {t, s.surface};
  }
  for (const auto& c : kFixedCircles) {
    const double t = hit_circle(origin, dir, c.c, c.r);
    if (t < best.t) best = {t, Surface::Matte};
  }
  for (const auto& c : people) {
    const double t = hit_circle(origin, dir, c.c, c.r);
    if (t < best.t) best = {t, Surface::Matte};
  }
  return best;
}

}  // namespace

std::optional<SceneReturn> RoomScene::sample_from(double x_mm, double y_mm, double angle_deg, std::int64_t t_ns) const {
  const double t = static_cast<double>(t_ns) * 1e-9;
  // Person A walks back and forth along y = 1.8 m; person B circles the left half of the room.
  const double phase = hash_unit(seed_, 1, 2) * 2 * kPi;
  const std::array<Circle, 2> people{{
      {{500 + 2000 * std::cos(2 * kPi * t / 16.0 + phase), 1800}, kPersonRadius},
      {{-1500 + 800 * std::cos(2 * kPi * t / 22.0), 300 + 800 * std::sin(2 * kPi * t / 22.0)}, kPersonRadius},
  }};
  const Vec origin{x_mm, y_mm};
  const Vec dir = direction(angle_deg);
  const Hit hit = nearest(origin, dir, people);
  const auto angle_key = static_cast<std::int64_t>(std::llround(angle_deg * 1000.0));
  const std::int64_t time_key = t_ns / 1000;

  SceneReturn out;
  switch (hit.surface) {
    case Surface::None: return out;
    case Surface::Window: {
      // Sunlight through the glass: no laser return, but the sensor sees bright spots at random
      // ranges for some directions, changing every 50 ms.
      // Spots are 0.5 degree wide so each has a direction the lidar can resolve.
      const std::int64_t bucket = t_ns / 50'000'000;
      const std::int64_t spot = angle_key / 500;
      if (hash_unit(seed_ ^ 0x51u, spot, bucket) < 0.35) {
        out.range_mm = 400 + 2600 * hash_unit(seed_ ^ 0x52u, spot, bucket);
        out.flag = PointFlag::AmbientLight;
      }
      return out;
    }
    case Surface::Mirror: {
      // The laser bounces off the mirror (a vertical wall: x flips) and comes back from whatever it
      // hits behind; the sensor reports the whole path, a ghost behind the wall.
      const Vec p{origin.x + dir.x * hit.t, origin.y + dir.y * hit.t};
      const Hit second = nearest(p, {-dir.x, dir.y}, people);
      if (second.t == kNoHit || second.surface != Surface::Matte) return out;
      out.range_mm = hit.t + second.t;
      out.flag = PointFlag::Specular;
      break;
    }
    case Surface::Matte: out.range_mm = hit.t; break;
  }
  const double sigma = 4.0 + 0.002 * out.range_mm;
  out.range_mm = std::max(1.0, out.range_mm + sigma * hash_normal(seed_, angle_key, time_key));
  return out;
}

}  // namespace ydscope
