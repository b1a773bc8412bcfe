#pragma once
// The spread of 2-D values (x x, x y, y y sums) and its two eigenvalues: how far a run of points
// is from a line (line_map), and how firmly walls' normals pin a shift (line_icp).
#include <cmath>

namespace ydscope::align {

struct Spread {
  double xx = 0;
  double xy = 0;
  double yy = 0;

  void add(double x, double y) {
    xx += x * x;
    xy += x * y;
    yy += y * y;
  }
  double larger() const { return 0.5 * (xx + yy) + root(); }
  double smaller() const { return 0.5 * (xx + yy) - root(); }

 private:
  double root() const { return std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy); }
};

}  // namespace ydscope::align
