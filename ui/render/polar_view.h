#pragma once
// The polar view as the app uses it: mouse handling (wheel zoom about the cursor, drag to pan,
// double-click to reset, right-click ruler, Shift+drag to sweep a sector, hover), auto-range, the point cloud rebuilt only when
// laps or settings change, and drawing through PolarRenderer plus the ImGui overlay.
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "ui/render/polar_overlay.h"
#include "ui/render/polar_renderer.h"
#include "ui/render/tile_cover.h"
#include "ui/view/geometry/auto_range_fit.h"
#include "ui/view/geometry/hit_test.h"
#include "ui/view/status/hover_gate.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/pixel_merge.h"
#include "ui/view/geometry/pose_drag.h"
#include "ui/view/settings/settings.h"
#include "ui/view/scene/source_cloud.h"
#include "ui/view/scene/source_clouds.h"

namespace ydscope::ui {

class PolarView {
 public:
  // `hover`: show the nearest point under a pointer that moves (off for screenshots).
  explicit PolarView(bool hover = true) : hover_gate_(hover) {}

  // The part of the window the view owns (window pixels).
  void set_viewport(Vec2 origin, Vec2 size);
  // The bottom of the view where the status line is written: grid labels keep out of it.
  void set_status_band(float px) { status_band_px_ = px; }
  // Mouse input from ImGui's IO for this frame; ignored when ImGui wants the mouse (over a panel).
  // `pointer_in_window` is the window system's word (GLFW_HOVERED); `now_s` any steady clock.
  void handle_input(ViewSettings& settings, bool pointer_in_window, double now_s);
  void reset(ViewSettings& settings);
  void clear_ruler() { ruler_.clear(); }
  // The watched sectors to outline, in the order the Sectors panel lists them.
  void set_sectors(std::vector<SectorShape> sectors) { sectors_ = std::move(sectors); }
  // A sector the user has just swept out with Shift+drag, as {from, to} degrees, once.
  std::optional<std::pair<float, float>> take_swept_sector();
  // Alt+drag moves and Ctrl+drag turns the selected source (several sources): while enabled, such a
  // drag no longer pans, and the frame's drag is taken once here.
  void enable_pose_drag(bool on) { pose_drag_enabled_ = on; }
  std::optional<PoseDrag> take_pose_drag();
  // "This is straight ahead" (the Sources tab's tool): while armed, the next left click on the view
  // does not pan or sweep; its world point is taken once here (forward_click.h).
  void arm_forward_click(bool on) { forward_click_armed_ = on; }
  std::optional<Vec2> take_forward_click();
  // Marks the cloud for a rebuild (a new lap, a source moved or dimmed).
  void invalidate() { shape_dirty_ = true; }
  // Fits the view to `extent_mm` from the origin when auto-range is on (the booth's framing).
  void auto_range_to(float extent_mm, const ViewSettings& settings);
  // Fits it to where the layers' returns lie, outliers left out (robust_extent_mm), with a margin.
  void auto_range(std::span<const SourceLayer> layers, const ViewSettings& settings);
  // Rebuilds the vertices if needed and uploads them; returns the cloud's statistics. Each source
  // is a layer posed into the common frame (source_cloud.h); one lidar is a layer at the identity
  // pose. `phase` (LapPhase) fades the persistence between laps: a change of it fades the cloud
  // again, without building it.
  const PointCloudStats& update_cloud(std::span<const SourceLayer> layers, const ViewSettings& settings, float phase);
  // Each source's position and heading, drawn in place of the lone lidar's mark (none: that mark).
  void set_source_marks(std::vector<SourceMark> marks) { marks_ = std::move(marks); }
  // The selected lidar's dropout ring (dropout_ring_overlay.h); empty: none drawn.
  void set_dropout_ring(std::optional<DropoutRingShape> ring) { dropouts_ = std::move(ring); }
  // The zones to colour by their states (zone_overlay.h); empty: none drawn.
  void set_zones(std::optional<ZoneShapes> zones) { zones_ = std::move(zones); }
  // The grid for the current view, and the labels, ruler, sectors and hover box into ImGui's
  // background draw list (under the panels). Before ImGui::Render.
  void lay_out(const LapHistory& history, const ViewSettings& settings);
  // One of the GL layers: the grid lines or the points. After ImGui::Render, before ImGui's own
  // draw data; the grid first.
  void draw_gl(const ViewSettings& settings, float framebuffer_scale, int framebuffer_height, GlLayer layer) const;
  // Both layers at once, the grid from `backdrop`, into `boxes` when the renderer can
  // (PolarRenderer::lay_points_over); false when the caller must lay and draw them.
  bool lay_gl_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes, const ViewSettings& settings,
                   float framebuffer_scale, int framebuffer_height) const;
  // Changes whenever the GL layer would draw something else (a new cloud or grid uploaded).
  std::uint64_t gl_generation() const { return gl_generation_; }
  // Changes whenever the grid is built again: the view moved, zoomed or was resized.
  std::uint64_t grid_generation() const { return grid_generation_; }
  // The view's tiles that the points uploaded last reach (their sprites at `point_size_px`, with
  // their rims); a frame whose grid is the last one's changes nothing outside these and the last's.
  // Worked out when asked, once for each new cloud or view.
  const TileCover& sprite_cover(float point_size_px);

  const ViewTransform& transform() const { return view_; }
  // The colours the cloud was last built with (range near/far following auto-range).
  const ColourParams& colours_in_use() const { return last_colours_; }
  // Points in the cloud, before those sharing a pixel were merged into one sprite.
  std::size_t points_shown() const { return points_shown_; }

 private:
  static PolarStyle style_of(const ViewSettings& settings);
  PolarRenderer renderer_;
  ViewTransform view_;
  Ruler ruler_;
  std::vector<PointVertex> vertices_;
  std::vector<LineVertex> grid_lines_;
  GridLayout grid_;
  float status_band_px_ = 0.0f;
  // The grid is rebuilt only when the view moved or its status band changed.
  struct GridKey {
    ViewTransform view;
    float status_band_px = -1.0f;
    friend bool operator==(const GridKey&, const GridKey&) = default;
  };
  GridKey grid_key_;
  PointCloudStats stats_;
  bool shape_dirty_ = true;  // every layer's cloud must be built again (the colours, the filter, asked)
  bool dirty_ = true;        // faded, merged and uploaded again (a new phase, a zoom)
  std::uint64_t gl_generation_ = 0;
  std::uint64_t grid_generation_ = 0;
  TileCover cover_;
  // What cover_ was worked out for: sprites moved (a new cloud, a zoom), the view moved, their size.
  std::uint64_t sprites_moved_ = 0;
  struct CoverKey {
    std::uint64_t sprites_moved = ~std::uint64_t{0};
    ViewTransform view;
    float point_size_px = 0.0f;
    friend bool operator==(const CoverKey&, const CoverKey&) = default;
  };
  CoverKey cover_key_;
  float last_phase_ = 0.0f;
  AutoRangeFit fit_;
  ViewSettings last_settings_;
  ColourParams last_colours_;
  HoverGate hover_gate_;
  std::optional<Vec2> hover_cursor_;
  std::optional<Vec2> cursor_world_;
  std::vector<SectorShape> sectors_;
  // Shift+drag: where it started and how far it has turned (signed, so a sweep may pass 180).
  std::optional<float> sweep_from_deg_;
  float sweep_last_deg_ = 0.0f;
  float sweep_turned_deg_ = 0.0f;
  std::optional<std::pair<float, float>> swept_;

  SourceClouds clouds_;  // built once a lap; vertices_ is their cloud faded and merged for this frame
  std::vector<SourceLayerKey> extent_from_;  // the layers extent_mm_ was measured on
  std::vector<SourceLayerKey> layer_keys_;   // this frame's, reused
  float extent_mm_ = 0.0f;                   // what auto-range fits: robust_extent_mm with a margin
  PixelMerger merger_;
  std::size_t points_shown_ = 0;
  std::optional<ViewTransform> merged_for_;  // the framing the cloud was merged and cut to
  std::vector<SourceMark> marks_;
  std::optional<DropoutRingShape> dropouts_;
  std::optional<ZoneShapes> zones_;
  bool pose_drag_enabled_ = false;
  std::optional<PoseDrag> pose_drag_;
  bool forward_click_armed_ = false;
  std::optional<Vec2> forward_click_;

  std::optional<SectorShape> sweep_shape() const;
  // Whether `layers` differ from those `last` was taken from; `last` then holds these.
  bool layers_changed(std::span<const SourceLayer> layers, std::vector<SourceLayerKey>& last);
  // The colours to build with this frame; marks the cloud dirty when they or the filter changed.
  ColourParams colours_for(const ViewSettings& settings, float phase, bool several_laps);
  void upload_if_dirty(float phase);
  // Copies into vertices_ the points of `cloud` whose sprites can reach into the view
  // (PolarRenderer::sprite_reach_px): before the merge, which then groups only what is seen.
  void copy_seen(const std::vector<PointVertex>& cloud, float point_size_px);
};

}  // namespace ydscope::ui
