#include "ui/render/theme.h"

#include <cmath>
#include <filesystem>

#include <imgui.h>

#include "ui/view/window/glyph_ranges.h"

namespace ydscope::ui {
namespace {

const char* find_font() {
  static const char* const candidates[] = {
      "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
      "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf",
      "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
  };
  for (const char* path : candidates) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) return path;
  }
  return nullptr;
}

ImFont* g_display_font = nullptr;

}  // namespace

ImFont* display_font() { return g_display_font; }

std::array<float, 4> sidebar_background() {
  // In the 8-bit steps the blend works in: ImGui's colour as its vertices carry it, the clear's.
  const ImU32 window = ImGui::GetColorU32(ImGuiCol_WindowBg);
  const float alpha = static_cast<float>((window >> IM_COL32_A_SHIFT) & 0xFF) / 255.0f;
  std::array<float, 4> fill{0.0f, 0.0f, 0.0f, 1.0f};
  for (int i = 0; i < 3; ++i) {
    const float over = static_cast<float>((window >> (IM_COL32_R_SHIFT + 8 * i)) & 0xFF) / 255.0f;
    const float under = std::round(kBackground[i] * 255.0f) / 255.0f;
    fill[static_cast<std::size_t>(i)] = over * alpha + under * (1.0f - alpha);
  }
  return fill;
}

Fonts apply_theme(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  ImGui::GetStyle() = ImGuiStyle();  // called again on a scale change: sizes scale from the defaults
  Fonts fonts;
  ImFontConfig config;
  config.OversampleH = 2;
  config.OversampleV = 2;
  static_assert(sizeof(ImWchar) == sizeof(kGlyphRanges[0]));
  const auto* ranges = reinterpret_cast<const ImWchar*>(kGlyphRanges);
  if (const char* path = find_font()) {
    fonts.system_font = io.Fonts->AddFontFromFileTTF(path, 16.0f * scale, &config, ranges) != nullptr;
    ImFontConfig large;
    large.OversampleH = 1;  // big glyphs need no sub-pixel oversampling; keeps the atlas small
    large.OversampleV = 1;
    g_display_font = io.Fonts->AddFontFromFileTTF(path, kDisplayFontPx * scale, &large, ranges);
  }
  if (!fonts.system_font) {
    ImFontConfig fallback;
    fallback.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&fallback);
  }

  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 6.0f;
  style.ChildRounding = 4.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.PopupRounding = 4.0f;
  style.ScrollbarRounding = 6.0f;
  style.TabRounding = 4.0f;
  style.WindowBorderSize = 0.0f;
  style.FrameBorderSize = 0.0f;
  style.WindowPadding = {12.0f, 10.0f};
  style.FramePadding = {8.0f, 4.0f};
  style.ItemSpacing = {8.0f, 6.0f};
  style.IndentSpacing = 14.0f;

  ImVec4* c = style.Colors;
  const ImVec4 accent{0.26f, 0.62f, 0.98f, 1.0f};
  c[ImGuiCol_Text] = {0.88f, 0.91f, 0.95f, 1.0f};
  c[ImGuiCol_TextDisabled] = {0.50f, 0.55f, 0.62f, 1.0f};
  c[ImGuiCol_WindowBg] = {0.070f, 0.082f, 0.105f, 0.94f};
  c[ImGuiCol_ChildBg] = {0.0f, 0.0f, 0.0f, 0.0f};
  c[ImGuiCol_PopupBg] = {0.08f, 0.09f, 0.12f, 0.98f};
  c[ImGuiCol_Border] = {0.20f, 0.24f, 0.30f, 0.60f};
  c[ImGuiCol_FrameBg] = {0.13f, 0.15f, 0.19f, 1.0f};
  c[ImGuiCol_FrameBgHovered] = {0.17f, 0.20f, 0.26f, 1.0f};
  c[ImGuiCol_FrameBgActive] = {0.20f, 0.24f, 0.31f, 1.0f};
  c[ImGuiCol_TitleBg] = {0.06f, 0.07f, 0.09f, 1.0f};
  c[ImGuiCol_TitleBgActive] = {0.08f, 0.10f, 0.13f, 1.0f};
  c[ImGuiCol_Header] = {0.14f, 0.17f, 0.22f, 1.0f};
  c[ImGuiCol_HeaderHovered] = {0.18f, 0.23f, 0.30f, 1.0f};
  c[ImGuiCol_HeaderActive] = {0.22f, 0.28f, 0.37f, 1.0f};
  c[ImGuiCol_Button] = {0.16f, 0.20f, 0.27f, 1.0f};
  c[ImGuiCol_ButtonHovered] = {0.22f, 0.32f, 0.45f, 1.0f};
  c[ImGuiCol_ButtonActive] = accent;
  c[ImGuiCol_CheckMark] = accent;
  c[ImGuiCol_SliderGrab] = accent;
  c[ImGuiCol_SliderGrabActive] = {0.45f, 0.75f, 1.0f, 1.0f};
  c[ImGuiCol_Separator] = {0.20f, 0.24f, 0.30f, 0.70f};
  c[ImGuiCol_PlotLines] = accent;
  c[ImGuiCol_PlotHistogram] = accent;
  c[ImGuiCol_ScrollbarBg] = {0.0f, 0.0f, 0.0f, 0.0f};

  style.ScaleAllSizes(scale);
  return fonts;
}

}  // namespace ydscope::ui
