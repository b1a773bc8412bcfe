#pragma once
// A fingerprint of what ImGui is about to draw: its vertices, indices, textures and clip
// rectangles. Two frames with the same fingerprint (and the same GL layer under them) look the
// same, so the app need not render and swap the second; on a software renderer a frame of a
// 1280x800 window costs about 13 ms of CPU, most of what an idle app spends.
#include <cstdint>

struct ImDrawData;

namespace ydscope::ui {

std::uint64_t draw_signature(const ImDrawData& data);

// Folds `value` into `signature` (for the GL layer's own state beside ImGui's).
std::uint64_t mix_signature(std::uint64_t signature, std::uint64_t value);

}  // namespace ydscope::ui
