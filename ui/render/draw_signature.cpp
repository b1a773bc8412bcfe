#include "ui/render/draw_signature.h"

#include <imgui.h>

#include <cstring>

namespace ydscope::ui {
namespace {

// FNV-1a over 8-byte words: a few thousand vertices a frame hash in well under a millisecond,
// and a chance collision costs one frame not redrawn until the next change.
constexpr std::uint64_t kPrime = 0x100000001b3ULL;
constexpr std::uint64_t kOffset = 0xcbf29ce484222325ULL;

std::uint64_t mix_bytes(std::uint64_t h, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, p + i, 8);
    h = (h ^ word) * kPrime;
  }
  for (; i < bytes; ++i) h = (h ^ p[i]) * kPrime;
  return h;
}

}  // namespace

std::uint64_t mix_signature(std::uint64_t signature, std::uint64_t value) {
  return mix_bytes(signature, &value, sizeof value);
}

std::uint64_t draw_signature(const ImDrawData& data) {
  std::uint64_t h = kOffset;
  h = mix_signature(h, static_cast<std::uint64_t>(data.CmdListsCount));
  for (int n = 0; n < data.CmdListsCount; ++n) {
    const ImDrawList& list = *data.CmdLists[n];
    h = mix_bytes(h, list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    h = mix_bytes(h, list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      h = mix_bytes(h, &cmd.ClipRect, sizeof cmd.ClipRect);
      h = mix_signature(h, reinterpret_cast<std::uintptr_t>(cmd.TextureId));
      h = mix_signature(h, (static_cast<std::uint64_t>(cmd.ElemCount) << 32) ^ cmd.IdxOffset);
      h = mix_signature(h, cmd.VtxOffset);
    }
  }
  return h;
}

}  // namespace ydscope::ui
