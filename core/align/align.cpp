#include "core/align/align.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace ydscope::align {
namespace {

std::string numbers(const AlignResult& r) {
  char text[200];
  std::snprintf(text, sizeof text, "%zu of %zu points (%.0f %%) on the reference's walls, residual %.1f mm", r.pairs,
                r.points, 100.0 * r.overlap, r.residual_mm);
  return text;
}

bool same_place(const RigidMotion& a, const RigidMotion& b) {
  const double turn = std::abs(std::remainder(a.turn_rad - b.turn_rad, 2 * std::numbers::pi));
  return turn < 2.0 * std::numbers::pi / 180.0 && std::hypot(a.shift.x - b.shift.x, a.shift.y - b.shift.y) < 100.0;
}

}  // namespace

Pose reported_pose(const Pose& pose) {
  Pose shown = pose;
  shown.x_m = std::round(pose.x_m * 1000.0) / 1000.0 + 0.0;
  shown.y_m = std::round(pose.y_m * 1000.0) / 1000.0 + 0.0;
  shown.yaw_deg = std::round(pose.yaw_deg * 100.0) / 100.0 + 0.0;
  return shown;
}

AlignResult align_to_reference(std::span<const Lap> reference_laps, const Pose& reference_pose,
                               std::span<const Lap> lidar_laps, const Pose& start, const AlignOptions& options) {
  AlignResult result;
  const std::vector<LapPoint> reference_own = steady_points(reference_laps, options.steady);
  const std::vector<LapPoint> lidar_own = steady_points(lidar_laps, options.steady);
  const std::vector<Point2> reference = to_common(reference_own, reference_pose);
  const std::vector<Point2> moving = to_common(lidar_own, start);
  result.points = moving.size();
  result.reference_points = reference.size();
  if (reference_laps.size() < 2 || lidar_laps.size() < 2) {
    result.message = "not enough laps: alignment needs at least 2 of each lidar to tell walls from passers-by";
    return result;
  }
  const LineMap walls(reference);
  const std::vector<Candidate> starts = coarse_search(reference, moving, pose_position_mm(start), options.coarse);
  std::vector<IcpFit> fits;
  for (const Candidate& c : starts) fits.push_back(refine(walls, moving, c.motion, options.icp));
  const IcpFit* best = nullptr;
  for (const IcpFit& fit : fits)
    if (!best || fit.pairs > best->pairs || (fit.pairs == best->pairs && fit.rms_mm < best->rms_mm)) best = &fit;
  if (!best || moving.empty()) {
    result.message = "not enough overlap: no steady points to match (" + std::to_string(moving.size()) +
                     " of the lidar, " + std::to_string(reference.size()) + " of the reference)";
    return result;
  }
  result.pairs = best->pairs;
  result.overlap = static_cast<double>(best->pairs) / static_cast<double>(moving.size());
  result.residual_mm = best->rms_mm;
  result.pose = moved_pose(start, best->motion);
  if (result.overlap < options.min_overlap || result.pairs < options.min_pairs) {
    char needed[120];
    std::snprintf(needed, sizeof needed, " (needs %.0f %% and %zu points)", 100.0 * options.min_overlap,
                  options.min_pairs);
    result.message = "not enough overlap: " + numbers(result) + needed +
                     "; place the lidars so they see more of the same walls, or give a closer start";
    return result;
  }
  if (best->weakest_direction < options.min_weakest_direction) {
    char weak[80];
    std::snprintf(weak, sizeof weak, " (%.2f, needs %.2f)", best->weakest_direction, options.min_weakest_direction);
    result.message = "not enough overlap: the common walls all run one way, so the shift along them is unknown" +
                     std::string(weak) + "; " + numbers(result);
    return result;
  }
  for (const IcpFit& fit : fits)
    if (&fit != best && !same_place(fit.motion, best->motion) &&
        static_cast<double>(fit.pairs) >= options.ambiguous_share * static_cast<double>(best->pairs)) {
      result.verdict = AlignVerdict::Ambiguous;
      result.message = "ambiguous: two different placements fit nearly as well (" + std::to_string(fit.pairs) +
                       " and " + std::to_string(best->pairs) + " points); give a closer start, " + numbers(result);
      return result;
    }
  result.verdict = AlignVerdict::Aligned;
  result.message = "aligned: " + numbers(result);
  return result;
}

}  // namespace ydscope::align
