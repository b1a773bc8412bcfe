#include "core/align/line_icp.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/align/spread.h"

namespace ydscope::align {
namespace {

struct Pair {
  Point2 p;  // moving point, moved
  LinePoint line;
  double distance;  // signed, along the normal
};

std::vector<Pair> pair_up(const LineMap& reference, std::span<const Point2> moving, const RigidMotion& motion,
                          double gate_mm) {
  std::vector<Pair> pairs;
  for (const Point2& m : moving) {
    const Point2 p = motion.apply(m);
    if (const auto line = reference.nearest(p, gate_mm))
      pairs.push_back({p, *line, (p.x - line->at.x) * line->normal.x + (p.y - line->at.y) * line->normal.y});
  }
  return pairs;
}

// Solves a x = b for a symmetric 3x3 a (Cramer); false when it is singular.
bool solve3(const double a[3][3], const double b[3], double x[3]) {
  const auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  if (std::abs(d) < 1e-12) return false;
  for (int k = 0; k < 3; ++k) {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] = c == k ? b[r] : a[r][c];
    x[k] = det(m) / d;
  }
  return true;
}

}  // namespace

IcpFit refine(const LineMap& reference, std::span<const Point2> moving, const RigidMotion& start,
              const IcpOptions& options) {
  IcpFit fit;
  fit.motion = start;
  double gate = options.first_gate_mm;
  for (std::size_t round = 0; round < options.max_rounds; ++round) {
    std::vector<Pair> pairs = pair_up(reference, moving, fit.motion, gate);
    if (pairs.size() < 3) break;
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& a, const Pair& b) { return std::abs(a.distance) < std::abs(b.distance); });
    pairs.resize(
        std::max<std::size_t>(3, static_cast<std::size_t>(options.keep_share * static_cast<double>(pairs.size()))));
    // Unknowns: a small extra turn w about the centre (mm-scaled by the lever arm) and a shift.
    // distance after = d + w * n.(perp(p - c)) + n.t
    double a[3][3] = {}, b[3] = {};
    const Point2 c{fit.motion.centre.x + fit.motion.shift.x, fit.motion.centre.y + fit.motion.shift.y};
    for (const Pair& pair : pairs) {
      const Point2 n = pair.line.normal;
      const double j[3] = {n.y * (pair.p.x - c.x) - n.x * (pair.p.y - c.y), n.x, n.y};
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) a[r][k] += j[r] * j[k];
        b[r] -= j[r] * pair.distance;
      }
    }
    double step[3];
    if (!solve3(a, b, step)) break;
    // Compose: turn by step[0] about the moved centre, then shift.
    const double turn = fit.motion.turn_rad + step[0];
    fit.motion.turn_rad = turn;
    fit.motion.shift.x += step[1];
    fit.motion.shift.y += step[2];
    const double lever = 5000.0;  // a turn matters as its move at 5 m
    const bool settled = std::abs(step[0]) * lever < 0.05 && std::hypot(step[1], step[2]) < 0.05;
    gate = std::max(options.last_gate_mm, gate * 0.7);
    if (settled && gate <= options.last_gate_mm) break;
  }
  // The verdict counts every pair within the last gate, untrimmed: overlap is what is there.
  const std::vector<Pair> pairs = pair_up(reference, moving, fit.motion, options.last_gate_mm);
  fit.pairs = pairs.size();
  if (pairs.empty()) return fit;
  double sum = 0;
  Spread normals;
  for (const Pair& pair : pairs) {
    sum += pair.distance * pair.distance;
    normals.add(pair.line.normal.x, pair.line.normal.y);
  }
  fit.rms_mm = std::sqrt(sum / static_cast<double>(pairs.size()));
  fit.weakest_direction = 2.0 * normals.smaller() / static_cast<double>(pairs.size());
  return fit;
}

}  // namespace ydscope::align
