#pragma once
// Turns the lap history into the vertex array the point shader draws in one call: positions in
// world millimetres plus a colour, newest lap last so it is drawn on top.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/protocol/interference_filter.h"
#include "ui/view/scene/colour_map.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/motion_background.h"

namespace ydscope::ui {

struct PointVertex {
  float x, y;    // world mm
  Rgba8 colour;  // premultiplied by nothing; the shader blends with alpha
  // How much of what lies under shows through where the sprite covers half a pixel, for a sprite
  // standing for several points (pixel_merge.h); below 0, a lone point's: 1 - alpha / 2.
  float half_clear = -1.0f;
};
static_assert(sizeof(PointVertex) == 16, "the shader's vertex layout expects 16 bytes");

struct InterferenceSettings {
  bool drop_specular = false;  // G1 flag 2
  bool drop_ambient = false;   // G1 flag 3
  bool show_ghosts = true;     // draw removed points faintly instead of hiding them
  // The protocol's filter (shared with the CLI) decides which points go.
  InterferenceFilter filter() const { return {drop_specular, drop_ambient}; }
  friend bool operator==(const InterferenceSettings&, const InterferenceSettings&) = default;
};

struct PointCloudStats {
  std::size_t drawn = 0;
  std::size_t ghosts = 0;
  std::size_t newest_specular_removed = 0;  // in the newest lap
  std::size_t newest_ambient_removed = 0;
  std::size_t newest_no_return = 0;  // range 0: no echo, never drawn
  // Several sources' statistics add up.
  void add(const PointCloudStats& other) {
    drawn += other.drawn;
    ghosts += other.ghosts;
    newest_specular_removed += other.newest_specular_removed;
    newest_ambient_removed += other.newest_ambient_removed;
    newest_no_return += other.newest_no_return;
  }
};

// Vertices of one lap of one source that fade alike. The newest lap's ghosts are runs of their
// own, since they do not fade.
struct FadeRun {
  std::uint32_t begin = 0, end = 0;  // vertex indices
  std::uint32_t age = 0;             // 0 for the newest lap
  std::uint32_t laps = 1;            // laps its history holds
  bool leaving = false;              // the oldest lap of a full history, which the next lap pushes out
  bool ghost = false;                // a filtered point drawn faintly
  float strength = 1.0f;             // what a dimmed source keeps of each channel (source_cloud.h)
};

// The cloud the point shader draws, kept between laps. A lap moves no point and changes no hue
// until the next one comes, so positions and hues are built once a lap and between laps only
// `fade_cloud` runs: sincos, the palette and the posing of 20 000 points at every frame had been
// a tenth of the app's CPU.
struct FadingCloud {
  std::vector<PointVertex> vertices;
  std::vector<FadeRun> runs;
  void clear() {
    vertices.clear();
    runs.clear();
  }
};

// One lap's points built as the newest lap's: each point's position and hue, the points the
// filter removes drawn as ghosts in runs of their own when it shows them. Where the lap stands in
// its history (its age, whether it is leaving, its ghosts once older) is set as the laps are put
// together (append_lap), so a lap is built once, not again at each lap after it.
struct LapCloud {
  std::uint64_t serial = 0;  // the HistoryLap's
  FadingCloud cloud;         // its runs' ages not yet set
  PointCloudStats stats;     // as the newest lap's
};

// Builds `lap` into `out` (keeping its capacity). Points with range 0 are not drawn. `motion`
// tells moving points from the room in Motion mode (without it every point is the room's).
void build_lap_cloud(const HistoryLap& lap, const ColourParams& colours, const InterferenceSettings& filter,
                     LapCloud& out, const MotionBackground* motion = nullptr);

// Where the lap `age` laps old stands in `history`'s fade: its age, the laps held, and whether it
// is the oldest of a full history, which the next lap pushes out.
FadeRun lap_place(const LapHistory& history, const ColourParams& colours, std::size_t age);

// Appends `lap` at `place` to `cloud`, and its share to `stats`: a lap older than the newest
// leaves its ghosts out (they would only smear) and counts only its drawn points.
void append_lap(const LapCloud& lap, const FadeRun& place, FadingCloud& cloud, PointCloudStats& stats);

// Clears `cloud` (keeping its capacity) and fills it with `history`'s laps, oldest first so the
// newest is drawn on top, in runs not yet faded (fade_cloud): each lap built and appended as above.
PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, FadingCloud& cloud,
                                  const MotionBackground* motion = nullptr);

// Sets each run's alpha (and in lap-age mode its hue) for `phase` (LapPhase, 0..1), how far the view
// is towards the next lap: every lap ages by that fraction of a lap, and when the history is full
// the oldest lap, which the next one will push out, fades away with it, so nothing pops.
void fade_cloud(FadingCloud& cloud, const ColourParams& colours, float phase);

}  // namespace ydscope::ui
