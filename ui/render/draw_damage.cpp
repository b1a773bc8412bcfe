#include "ui/render/draw_damage.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ydscope::ui {

bool DrawDamage::Triangle::operator==(const Triangle& other) const {
  // Field by field: the struct's padding is not part of the picture.
  return std::memcmp(corner, other.corner, sizeof corner) == 0 && std::memcmp(&clip, &other.clip, sizeof clip) == 0 &&
         texture == other.texture;
}

void DrawDamage::resolve(const ImDrawList& list, std::vector<Triangle>& out) {
  out.clear();
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    if (cmd.UserCallback != nullptr) continue;  // the app sets none; nothing of the picture
    for (unsigned int i = 0; i + 2 < cmd.ElemCount; i += 3) {
      Triangle t;
      for (int k = 0; k < 3; ++k)
        t.corner[k] =
            list.VtxBuffer[static_cast<int>(cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + i) + k])];
      t.clip = cmd.ClipRect;
      t.texture = cmd.TextureId;
      out.push_back(t);
    }
  }
}

DisplayBox DrawDamage::bounds(const std::vector<Triangle>& triangles, std::size_t from, std::size_t to) {
  DisplayBox box;
  for (std::size_t i = from; i < to; ++i) {
    const Triangle& t = triangles[i];
    DisplayBox own{t.corner[0].pos.x, t.corner[0].pos.y, t.corner[0].pos.x, t.corner[0].pos.y};
    for (const ImDrawVert& v : t.corner)
      own = {std::min(own.x0, v.pos.x), std::min(own.y0, v.pos.y), std::max(own.x1, v.pos.x),
             std::max(own.y1, v.pos.y)};
    // A pixel is drawn when its centre is inside: whole pixels around the corners cover it.
    own = {std::floor(own.x0), std::floor(own.y0), std::ceil(own.x1) + 1.0f, std::ceil(own.y1) + 1.0f};
    box = box.united(own.intersected({t.clip.x, t.clip.y, t.clip.z, t.clip.w}));
  }
  return box;
}

std::optional<std::vector<DisplayBox>> DrawDamage::update(const ImDrawData& data) {
  resolved_.resize(static_cast<std::size_t>(std::max(data.CmdListsCount, 0)));
  for (int n = 0; n < data.CmdListsCount; ++n) resolve(*data.CmdLists[n], resolved_[static_cast<std::size_t>(n)]);
  const bool comparable = known_ && resolved_.size() == lists_.size();
  std::vector<DisplayBox> boxes;
  for (std::size_t n = 0; comparable && n < resolved_.size(); ++n) {
    const std::vector<Triangle>& now = resolved_[n];
    const std::vector<Triangle>& was = lists_[n];
    const std::size_t shorter = std::min(now.size(), was.size());
    std::size_t head = 0;
    while (head < shorter && now[head] == was[head]) ++head;
    if (head == now.size() && head == was.size()) continue;  // this list draws as it did
    std::size_t tail = 0;
    while (tail < shorter - head && now[now.size() - 1 - tail] == was[was.size() - 1 - tail]) ++tail;
    const DisplayBox box = bounds(now, head, now.size() - tail).united(bounds(was, head, was.size() - tail));
    if (!box.empty()) boxes.push_back(box);
  }
  lists_.swap(resolved_);
  known_ = true;
  if (!comparable) return std::nullopt;
  return boxes;
}

}  // namespace ydscope::ui
