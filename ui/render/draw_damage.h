#pragma once
// Where ImGui's picture changed since the last frame. A streaming view changes at every frame,
// but the panels beside it change a figure or two now and then, and on a software renderer
// rasterising the unchanged panels again was about a third of a frame's CPU. Each draw list's
// triangles (resolved to their vertices, with their clip rectangle and texture) are compared with
// the last frame's, command by command where the two frames have the same commands (a plot's data
// is a command of its own, under its own clip rectangle), else the list whole. In each, after the
// longest common head and tail, the triangles are walked until they differ and then a little
// further on to where they agree again: each stretch between is a change, and its bounds, old and
// new, clipped, a box of damage. Two figures that changed apart in one panel are two small boxes,
// not one round all between them. A frame whose lists all match the last frame's has none, and
// need not be drawn at all.
#include <optional>
#include <vector>

#include <imgui.h>

#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class DrawDamage {
 public:
  // The boxes where `data` draws otherwise than the frame last given, one for each stretch that
  // changed (at most kMaxStretches in a command); none when the frame repeats the last.
  // std::nullopt when the two cannot be compared (the first frame, or another number of draw
  // lists): take it all as changed.
  std::optional<std::vector<DisplayBox>> update(const ImDrawData& data);
  // The next frame is compared with nothing (after a frame drawn by other means).
  void forget() { known_ = false; }

  // How far on (in triangles, on either side) a changed stretch looks for the two frames to agree
  // again, how many triangles in a row must agree, and how many stretches a command may have
  // before the rest of what differs in it counts as one.
  static constexpr std::size_t kLookAhead = 32;
  static constexpr std::size_t kAgreeing = 3;
  static constexpr std::size_t kMaxStretches = 6;

 private:
  struct Triangle {
    ImDrawVert corner[3];
    ImVec4 clip;
    ImTextureID texture;
    bool operator==(const Triangle& other) const;
  };
  struct Command {
    ImVec4 clip;
    ImTextureID texture;
    std::size_t end;  // one past its last triangle in the list's
    bool same_as(const Command& other) const;
  };
  struct Resolved {
    std::vector<Triangle> triangles;
    std::vector<Command> commands;
  };
  // Triangles [from, to) of a frame's list.
  struct Part {
    const std::vector<Triangle>* triangles;
    std::size_t from, to;
  };
  static void resolve(const ImDrawList& list, Resolved& out);
  static DisplayBox bounds(const std::vector<Triangle>& triangles, std::size_t from, std::size_t to);
  // Adds a box round each stretch where `now` draws otherwise than `was`.
  static void compare(Part now, Part was, std::vector<DisplayBox>& boxes);

  std::vector<Resolved> lists_, resolved_;  // the last frame's; this frame's, reused
  bool known_ = false;
};

}  // namespace ydscope::ui
