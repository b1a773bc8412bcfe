#include "ui/render/imgui_within.h"

#include <vector>

#include <backends/imgui_impl_opengl3.h>

namespace ydscope::ui {

void render_imgui_within(ImDrawData& data, const DisplayBox& box) {
  std::vector<ImVec4> kept;
  for (int n = 0; n < data.CmdListsCount; ++n)
    for (ImDrawCmd& cmd : data.CmdLists[n]->CmdBuffer) {
      kept.push_back(cmd.ClipRect);
      const DisplayBox cut =
          DisplayBox{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w}.intersected(box);
      // An empty clip rectangle is one the backend skips.
      cmd.ClipRect = cut.empty() ? ImVec4{box.x0, box.y0, box.x0, box.y0} : ImVec4{cut.x0, cut.y0, cut.x1, cut.y1};
    }
  ImGui_ImplOpenGL3_RenderDrawData(&data);
  std::size_t i = 0;
  for (int n = 0; n < data.CmdListsCount; ++n)
    for (ImDrawCmd& cmd : data.CmdLists[n]->CmdBuffer) cmd.ClipRect = kept[i++];
}

}  // namespace ydscope::ui
