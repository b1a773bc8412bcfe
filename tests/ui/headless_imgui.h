#pragma once
// A real ImGui context with the app's fonts and no display: panels lay out and fill their draw
// lists, and nothing is drawn.
#include <imgui.h>

#include "ui/render/theme.h"

namespace ydscope::ui {

class HeadlessImGui {
 public:
  HeadlessImGui(float width, float height) {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::GetIO().DisplaySize = {width, height};
    apply_theme(1.0f);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;
};

}  // namespace ydscope::ui
