#pragma once
// Points that fall in the same pixel are drawn as one sprite. With ten laps kept, a static wall
// puts dozens of points on each of its pixels, and a software renderer (Mesa's llvmpipe, what
// robots' boards, VMs and CI draw with) pays for every one of them at every frame, because the
// fade moves. Merging them on the CPU, with the same "over" rule the GPU's blend applies, gives
// the picture the stack would have given for a fraction of the raster work.
#include <cstdint>
#include <vector>

#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {

// Replaces a cloud (in draw order: the last point is on top) with one sprite per cell of `cell_mm`
// square that holds any, in the order of their topmost points. Each sprite carries the stack's
// colour and alpha and, in `half_clear`, what shows through the stack at half coverage, from which
// the point shader draws the rim the stack's rims would have built up. Where the cells would leave
// more than three quarters of the points (a scene that moves), the cloud is left as it was, and
// the next kCloudsBetweenLooks clouds are not looked at.
//
// Kept between frames: which points share a pixel is worked out again only when the points moved
// (a new lap, a zoom), since between laps only their fade changes; nothing is allocated once
// warmed up.
class PixelMerger {
 public:
  // Clouds drawn as they are after one whose merge would not have paid: about a second at the
  // display's rate, four at a frame a lap.
  static constexpr int kCloudsBetweenLooks = 30;

  void merge(std::vector<PointVertex>& points, float cell_mm);

 private:
  struct Cell {
    std::uint64_t key = 0;
    std::uint32_t slot = 0;
    std::uint32_t round = 0;  // the grouping that filled it; older ones read as empty, so no clearing
  };
  struct Slot {
    float x = 0, y = 0;         // the topmost member's position: it is what shows
    float r = 0, g = 0, b = 0;  // premultiplied colour of the stack so far, 0..1
    float a = 0;                // the stack's alpha so far, 0..1
    float half_clear = 1;       // what shows through the stack where each member covers half
  };

  bool same_points(const std::vector<PointVertex>& points, float cell_mm) const;
  void group(const std::vector<PointVertex>& points, float cell_mm);
  std::uint32_t slot_for(std::uint64_t key, float x, float y);
  static void lay_under(Slot& slot, const PointVertex& p);
  static PointVertex sprite_of(const Slot& slot);

  std::vector<Cell> table_;
  int table_shift_ = 64;  // 64 - log2 of the table's size
  std::uint32_t round_ = 0;
  // The grouping of the points last merged: their positions, each one's slot, the cell size.
  std::vector<float> positions_;
  std::vector<std::uint32_t> slot_of_;
  float cell_mm_ = 0.0f;
  std::vector<Slot> slots_;  // made top first
  // Whether the last grouping merged enough to pay, and if not, how many more clouds to draw as
  // they are before grouping again: a scene that moves stays one for a while.
  bool worth_merging_ = false;
  int clouds_until_next_look_ = 0;
};

}  // namespace ydscope::ui
