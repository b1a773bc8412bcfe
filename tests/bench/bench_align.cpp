// Alignment against known poses, swept wider than the align tests: the room scene at four poses
// (one mounted upside down) and the booth at two, each with two scene seeds and eight rough
// starts (turned up to 30 degrees and shifted 0.5 m, every way). Prints per pose and seed how
// many starts aligned, the worst position and yaw error against the truth, the residual, the
// overlap, and the median CPU time of one alignment (docs/align.md quotes it).
//
//   bench_align
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include "align/scene_laps.h"
#include "core/align/align.h"

namespace {

using namespace ydscope;

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace

int main() {
  struct Case {
    const char* scene;
    Pose truth;
  };
  const Case cases[] = {{"room", {0.6, -0.4, 35, false}},   {"room", {-0.8, 0.5, -120, false}},
                        {"room", {0.3, 0.9, 170, false}},   {"room", {0.6, -0.4, 35, true}},
                        {"booth", {-0.5, -0.3, 60, false}}, {"booth", {0.7, -0.6, -25, false}}};
  const double turns[] = {30, -30, 15, -20, 0, 30, -30, 10};
  const double shifts[][2] = {{0.5, 0}, {0, -0.5},      {-0.35, 0.35}, {0.3, 0.4},
                              {0, 0},   {-0.35, -0.35}, {0.35, -0.35}, {0, 0.5}};
  std::vector<double> times;
  for (const Case& c : cases)
    for (const std::uint64_t seed : {3ull, 11ull}) {
      const auto reference = test::scene_laps(c.scene, std::nullopt, 8, seed);
      const auto lidar = test::scene_laps(c.scene, c.truth, 8, seed);
      double worst_mm = 0, worst_deg = 0, residual = 0, overlap = 0;
      int aligned = 0;
      for (int i = 0; i < 8; ++i) {
        Pose start = c.truth;
        start.x_m += shifts[i][0];
        start.y_m += shifts[i][1];
        start.yaw_deg += turns[i];
        const double before = cpu_ms();
        const align::AlignResult r = align::align_to_reference(reference, Pose{}, lidar, start);
        times.push_back(cpu_ms() - before);
        if (r.verdict != align::AlignVerdict::Aligned) {
          std::printf("  not aligned from %s: %s\n", format_pose(start).c_str(), r.message.c_str());
          continue;
        }
        ++aligned;
        worst_mm = std::max(worst_mm, 1000.0 * std::hypot(r.pose.x_m - c.truth.x_m, r.pose.y_m - c.truth.y_m));
        worst_deg = std::max(worst_deg, std::abs(std::remainder(r.pose.yaw_deg - c.truth.yaw_deg, 360.0)));
        residual = r.residual_mm;
        overlap = r.overlap;
      }
      std::printf("%-5s %-16s seed %2llu: %d/8 aligned, worst %.1f mm %.3f deg, residual %.1f mm, overlap %.0f %%\n",
                  c.scene, format_pose(c.truth).c_str(), static_cast<unsigned long long>(seed), aligned, worst_mm,
                  worst_deg, residual, 100.0 * overlap);
    }
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  std::printf("one alignment: median %.0f ms of CPU over %zu\n", times[times.size() / 2], times.size());
  return 0;
}
