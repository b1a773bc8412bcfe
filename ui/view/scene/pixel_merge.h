#pragma once
// Points that fall in the same pixel are drawn as one sprite. With ten laps kept, a static wall
// puts dozens of points on each of its pixels, and a software renderer (Mesa's llvmpipe, what
// robots' boards, VMs and CI draw with) pays for every one of them at every frame, because the
// fade moves. Merging them on the CPU, with the same "over" rule the GPU's blend applies, gives
// the picture the stack would have given for a fraction of the raster work.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {

// Replaces a cloud (in draw order: the last point is on top) with one sprite per cell of `cell_mm`
// square that holds any, in the order of their topmost points. Each sprite carries the stack's
// colour and alpha and, in `half_clear`, what shows through the stack at half coverage, from which
// the point shader draws the rim the stack's rims would have built up. Where the cells would leave
// more than three quarters of the points (a scene that moves), the cloud is left as it was, and
// the next kCloudsBetweenLooks clouds are not looked at; so it is where the points spread over more
// than kMaxCells cells (the caller keeps to what the view shows, so this is a zoom far out of it).
//
// Kept between frames: which points share a pixel is worked out again only when the points moved
// (a new lap, a zoom), since between laps only their fade changes; nothing is allocated once
// warmed up.
class PixelMerger {
 public:
  // Clouds drawn as they are after one whose merge would not have paid: about a second at the
  // display's rate, four at a frame a lap.
  static constexpr int kCloudsBetweenLooks = 30;
  // A 4K screen's pixels twice over: the grid of cells is 4 bytes a cell.
  static constexpr std::size_t kMaxCells = std::size_t{1} << 24;

  void merge(std::vector<PointVertex>& points, float cell_mm);

 private:
  struct Slot {
    float x = 0, y = 0;         // the topmost member's position: it is what shows
    float r = 0, g = 0, b = 0;  // premultiplied colour of the stack so far, 0..255
    float a = 0;                // the stack's alpha so far, 0..1
    float half_clear = 1;       // what shows through the stack where each member covers half
  };
  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};

  bool same_points(const std::vector<PointVertex>& points, float cell_mm) const;
  // False when the points spread over more than kMaxCells cells.
  bool group(const std::vector<PointVertex>& points, float cell_mm);
  static void lay_under(Slot& slot, const PointVertex& p);
  static PointVertex sprite_of(const Slot& slot);

  // The cells over the points' bounds, row by row, each the slot of its stack or kNoSlot. A grid,
  // not a hash table: a lap's points come round in order, so neighbours in the cloud are
  // neighbours here and stay in the cache (hashed, every point was a miss).
  std::vector<std::uint32_t> cells_;
  std::vector<std::uint32_t> cell_of_slot_;  // to empty the grid again after a grouping
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
