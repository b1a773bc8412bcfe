#pragma once
// The polar view of a frame. One lidar is drawn around itself as always; several in the common
// frame, each at its pose (source_cloud); or, with View > split, two to four side by side, each in
// a view of its own. Laid out every frame; drawn with GL only when the picture would change.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "app/gui/source_list.h"
#include "ui/render/backdrop_picture.h"
#include "ui/render/draw_damage.h"
#include "ui/render/screen_boxes.h"
#include "ui/render/polar_view.h"
#include "ui/render/tile_cover.h"
#include "ui/view/settings/settings.h"

namespace ydscope::gui {

// What a frame's layout needs besides the sources and the settings.
struct ViewFrame {
  float left = 0.0f;  // the view's part of the window (window pixels): right of the sidebar
  float width = 0.0f;
  float height = 0.0f;
  bool hovered = false;          // the pointer is over the window (the window system's word)
  double now_s = 0.0;            // the app's steady clock
  float phase = 0.0f;            // how far the fading persistence is between two laps
  bool legend_in_booth = false;  // the booth view names the sources in its own large legend
  bool booth = false;            // the booth view frames the scene it sees (ui/view/scene/booth_framing.h)
};

class ViewStage {
 public:
  // `interactive`: hovering shows the nearest point (off for screenshot runs).
  explicit ViewStage(bool interactive)
      : interactive_(interactive), view_(std::make_unique<ui::PolarView>(interactive)) {}

  // The common view: its ruler, sector outlines, colours, and the rebuild a change asks for.
  ui::PolarView& view() { return *view_; }
  const ui::PolarView& view() const { return *view_; }
  // Lays out the frame's view and fills the selected source's model with what it shows. Alt/Ctrl+
  // drag and Shift+drag on the common view become requests in the selected source's model.
  void lay_out(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame);
  // Renders the GL layer and ImGui's draw data where the frame differs from the last one drawn:
  // with `partial` (the window keeps its last picture: window_present.h) only in the boxes that
  // changed, otherwise the whole window once anything did. Nothing is drawn when the frame would
  // look exactly like the last and nothing asks for it (`must_draw`: a screenshot, or a window the
  // system lost, which are drawn whole).
  ui::DrawnFrame render_if_changed(const ui::ViewSettings& settings, float framebuffer_scale, int framebuffer_width,
                                   int framebuffer_height, bool must_draw, bool partial);

 private:
  void lay_out_common(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame);
  void lay_out_split(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame);
  // Each shown source's laps at its pose, and its mark.
  std::span<const ui::SourceLayer> layers_of(const SourceList& sources);
  // Changes whenever the GL layer of the view (or of the split view's tiles) would draw otherwise.
  std::uint64_t gl_generation() const;
  // How a frame's boxes are drawn.
  struct BoxPlan {
    bool points_once = false;  // every point lies inside the boxes: drawn in one pass over the view
    bool backdrop = false;     // the view's parts laid from the grid's picture, not cleared and drawn
  };
  // Clears each box and draws in it the GL layers (inside `view`) and ImGui's draw data; their pixels.
  std::vector<ui::PixelBox> draw_boxes(std::span<const ui::DisplayBox> boxes, const ui::DisplayBox& view,
                                       const BoxPlan& plan, const ui::ViewSettings& settings, float framebuffer_scale,
                                       int framebuffer_width, int framebuffer_height);

  bool interactive_;
  std::unique_ptr<ui::PolarView> view_;
  std::vector<std::unique_ptr<ui::PolarView>> tiles_;  // the split view's, one per source shown
  bool split_ = false;                                 // this frame is laid out as the split view
  float sidebar_px_ = 0.0f;                            // the sidebar's width (window pixels), 0: none
  std::vector<ui::SourceLayer> layers_;                // this frame's, reused
  std::vector<ui::SourceMark> marks_;
  // What the last frame drawn was drawn with: a new layout is drawn whole, a new GL layer in the view.
  struct DrawnLayout {
    int width = 0, height = 0;
    float scale = 0.0f, sidebar_px = 0.0f;
    friend bool operator==(const DrawnLayout&, const DrawnLayout&) = default;
  };
  struct DrawnGl {
    std::uint64_t generation = 0;
    std::uint64_t grid_generation = 0;  // the common view's; the split view's tiles are drawn whole
    bool split = false;
    bool grid = false;
    float point_size_px = 0.0f;
    friend bool operator==(const DrawnGl&, const DrawnGl&) = default;
    // `now` differs from this only in the common view's points: the rest of it is as drawn.
    bool points_only_changed_to(const DrawnGl& now) const;
  };
  // The parts of `view` a frame whose points alone changed draws again: where they were and are.
  std::vector<ui::DisplayBox> points_changed_in(const ui::DisplayBox& view, float point_size_px);
  // What the grid's picture is drawn for: the view's framing, the grid shown, the window.
  struct BackdropKey {
    std::uint64_t grid_generation = 0;
    bool grid = false;
    int width = 0, height = 0;
    ui::DisplayBox view;
    friend bool operator==(const BackdropKey&, const BackdropKey&) = default;
  };
  BackdropKey backdrop_key(const ui::ViewSettings& settings, const ui::DisplayBox& view, int framebuffer_width,
                           int framebuffer_height) const;
  DrawnLayout drawn_layout_;
  DrawnGl drawn_gl_;
  ui::TileCover drawn_cover_;                      // where the common view's points were in the last frame drawn
  std::unique_ptr<ui::BackdropPicture> backdrop_;  // made the first time a frame of points lays it
  std::optional<BackdropKey> backdrop_holds_;
  ui::DrawDamage damage_;  // where ImGui's picture changed since the last frame
};

}  // namespace ydscope::gui
