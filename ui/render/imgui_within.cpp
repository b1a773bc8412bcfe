#include "ui/render/imgui_within.h"

#include <algorithm>
#include <vector>

#include <backends/imgui_impl_opengl3.h>

namespace ydscope::ui {
namespace {

// Whether the triangle at `first` of `list`'s indices (from `base` in its vertices) reaches `box`.
bool reaches(const ImDrawList& list, unsigned first, unsigned base, const DisplayBox& box) {
  float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
  for (unsigned corner = 0; corner < 3; ++corner) {
    const ImVec2 p = list.VtxBuffer[static_cast<int>(base + list.IdxBuffer[static_cast<int>(first + corner)])].pos;
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  return x1 > box.x0 && x0 < box.x1 && y1 > box.y0 && y0 < box.y1;
}

}  // namespace

void render_imgui_within(ImDrawData& data, std::span<const DisplayBox> boxes) {
  std::vector<ImVector<ImDrawCmd>> kept(static_cast<std::size_t>(data.CmdListsCount));
  std::vector<int> index_counts(static_cast<std::size_t>(data.CmdListsCount));
  std::vector<ImDrawIdx> extra;
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
      for (const DisplayBox& box : boxes) {
        const DisplayBox inside =
            DisplayBox{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w}.intersected(box);
        if (inside.empty()) continue;
        ImDrawCmd part = cmd;
        part.ClipRect = ImVec4{inside.x0, inside.y0, inside.x1, inside.y1};
        if (boxes.size() > 1) {
          // Of several boxes each takes only the triangles that reach it: every vertex of a command
          // repeated in every box went through the pipeline again, and a command drawing over the
          // whole view (its labels and marks) reached nearly all of them.
          const std::size_t from = extra.size();
          for (unsigned i = cmd.IdxOffset; i < cmd.IdxOffset + cmd.ElemCount; i += 3)
            if (reaches(list, i, cmd.VtxOffset, inside))
              extra.insert(extra.end(), &list.IdxBuffer[static_cast<int>(i)], &list.IdxBuffer[static_cast<int>(i)] + 3);
          const std::size_t count = extra.size() - from;
          if (count == 0) continue;
          if (count < cmd.ElemCount) {
            part.IdxOffset = first_extra + static_cast<unsigned>(from);
            part.ElemCount = static_cast<unsigned>(count);
          } else {
            extra.resize(from);  // all of it: the command's own indices will do
          }
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
