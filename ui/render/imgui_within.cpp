#include "ui/render/imgui_within.h"

#include <algorithm>
#include <vector>

#include <backends/imgui_impl_opengl3.h>

namespace ydscope::ui {
namespace {

// The box round the triangle at `first` of `list`'s indices (from `base` in its vertices).
DisplayBox triangle_bounds(const ImDrawList& list, unsigned first, unsigned base) {
  DisplayBox bounds{1e30f, 1e30f, -1e30f, -1e30f};
  for (unsigned corner = 0; corner < 3; ++corner) {
    const ImVec2 p = list.VtxBuffer[static_cast<int>(base + list.IdxBuffer[static_cast<int>(first + corner)])].pos;
    bounds = {std::min(bounds.x0, p.x), std::min(bounds.y0, p.y), std::max(bounds.x1, p.x), std::max(bounds.y1, p.y)};
  }
  return bounds;
}

// Whether a triangle within `bounds` reaches `box` (a line of no width still does).
bool reaches(const DisplayBox& bounds, const DisplayBox& box) {
  return bounds.x1 > box.x0 && bounds.x0 < box.x1 && bounds.y1 > box.y0 && bounds.y0 < box.y1;
}

}  // namespace

void render_imgui_within(ImDrawData& data, std::span<const DisplayBox> boxes) {
  std::vector<ImVector<ImDrawCmd>> kept(static_cast<std::size_t>(data.CmdListsCount));
  std::vector<int> index_counts(static_cast<std::size_t>(data.CmdListsCount));
  std::vector<ImDrawIdx> extra;
  std::vector<DisplayBox> cuts;                // a command's clip rectangle cut to each box it reaches
  std::vector<std::vector<ImDrawIdx>> chosen;  // for each cut, the command's triangles that reach it
  for (int n = 0; n < data.CmdListsCount; ++n) {
    ImDrawList& list = *data.CmdLists[n];
    const auto first_extra = static_cast<unsigned>(list.IdxBuffer.Size);
    index_counts[static_cast<std::size_t>(n)] = list.IdxBuffer.Size;
    extra.clear();
    ImVector<ImDrawCmd> cut;
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      // A callback (none of ours today) runs once, as ImGui would run it.
      if (cmd.UserCallback != nullptr) {
        cut.push_back(cmd);
        continue;
      }
      cuts.clear();
      for (const DisplayBox& box : boxes)
        if (const DisplayBox inside =
                DisplayBox{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w}.intersected(box);
            !inside.empty())
          cuts.push_back(inside);
      if (cuts.size() == 1 && boxes.size() == 1) {
        cut.push_back(cmd);
        cut.back().ClipRect = ImVec4{cuts[0].x0, cuts[0].y0, cuts[0].x1, cuts[0].y1};
        continue;
      }
      // Of several boxes each takes only the triangles that reach it: every vertex of a command
      // repeated in every box went through the pipeline again, and a command drawing over the
      // whole view (its labels and marks) reached nearly all of them. One walk over the
      // triangles hands each to the boxes it reaches.
      if (chosen.size() < cuts.size()) chosen.resize(cuts.size());
      for (std::size_t k = 0; k < cuts.size(); ++k) chosen[k].clear();
      for (unsigned i = cmd.IdxOffset; i < cmd.IdxOffset + cmd.ElemCount; i += 3) {
        const DisplayBox bounds = triangle_bounds(list, i, cmd.VtxOffset);
        for (std::size_t k = 0; k < cuts.size(); ++k)
          if (reaches(bounds, cuts[k]))
            chosen[k].insert(chosen[k].end(), &list.IdxBuffer[static_cast<int>(i)],
                             &list.IdxBuffer[static_cast<int>(i)] + 3);
      }
      for (std::size_t k = 0; k < cuts.size(); ++k) {
        if (chosen[k].empty()) continue;
        ImDrawCmd part = cmd;
        part.ClipRect = ImVec4{cuts[k].x0, cuts[k].y0, cuts[k].x1, cuts[k].y1};
        if (chosen[k].size() < cmd.ElemCount) {  // else all of it: the command's own indices will do
          part.IdxOffset = first_extra + static_cast<unsigned>(extra.size());
          part.ElemCount = static_cast<unsigned>(chosen[k].size());
          extra.insert(extra.end(), chosen[k].begin(), chosen[k].end());
        }
        cut.push_back(part);
      }
    }
    // The chosen triangles' indices go after the list's own for the call, and are taken off after.
    for (const ImDrawIdx index : extra) list.IdxBuffer.push_back(index);
    list.CmdBuffer.swap(cut);
    kept[static_cast<std::size_t>(n)].swap(cut);
  }
  ImGui_ImplOpenGL3_RenderDrawData(&data);
  for (int n = 0; n < data.CmdListsCount; ++n) {
    data.CmdLists[n]->CmdBuffer.swap(kept[static_cast<std::size_t>(n)]);
    data.CmdLists[n]->IdxBuffer.resize(index_counts[static_cast<std::size_t>(n)]);
  }
}

}  // namespace ydscope::ui
