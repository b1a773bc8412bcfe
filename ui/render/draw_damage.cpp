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

bool DrawDamage::Command::same_as(const Command& other) const {
  return std::memcmp(&clip, &other.clip, sizeof clip) == 0 && texture == other.texture;
}

void DrawDamage::resolve(const ImDrawList& list, Resolved& out) {
  out.triangles.clear();
  out.commands.clear();
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    if (cmd.UserCallback != nullptr) continue;  // the app sets none; nothing of the picture
    for (unsigned int i = 0; i + 2 < cmd.ElemCount; i += 3) {
      Triangle t;
      for (int k = 0; k < 3; ++k)
        t.corner[k] =
            list.VtxBuffer[static_cast<int>(cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + i) + k])];
      t.clip = cmd.ClipRect;
      t.texture = cmd.TextureId;
      out.triangles.push_back(t);
    }
    out.commands.push_back({cmd.ClipRect, cmd.TextureId, out.triangles.size()});
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

void DrawDamage::compare(Part now, Part was, std::vector<DisplayBox>& boxes) {
  const std::vector<Triangle>& n = *now.triangles;
  const std::vector<Triangle>& w = *was.triangles;
  // What both begin and end with drew the same.
  while (now.from < now.to && was.from < was.to && n[now.from] == w[was.from]) ++now.from, ++was.from;
  while (now.to > now.from && was.to > was.from && n[now.to - 1] == w[was.to - 1]) --now.to, --was.to;
  // In step from (i, j): kAgreeing triangles agree there, or both parts end there together.
  const auto in_step = [&](std::size_t i, std::size_t j) {
    for (std::size_t k = 0; k < kAgreeing; ++k) {
      const bool more_now = i + k < now.to, more_was = j + k < was.to;
      if (!more_now || !more_was) return !more_now && !more_was;
      if (!(n[i + k] == w[j + k])) return false;
    }
    return true;
  };
  std::size_t i = now.from, j = was.from, stretches = 0;
  while (i < now.to || j < was.to) {
    if (i < now.to && j < was.to && n[i] == w[j]) {
      ++i, ++j;
      continue;
    }
    // The nearest place on where the two agree again, taking di more of this frame's triangles
    // and dj more of the last's; none near, or too many stretches already: all the rest changed.
    std::size_t next_i = now.to, next_j = was.to;
    bool again = ++stretches >= kMaxStretches;
    for (std::size_t d = 1; !again && d <= 2 * kLookAhead; ++d) {
      for (std::size_t di = d > kLookAhead ? d - kLookAhead : 0; !again && di <= std::min(d, kLookAhead); ++di) {
        const std::size_t dj = d - di;
        if (i + di <= now.to && j + dj <= was.to && in_step(i + di, j + dj))
          next_i = i + di, next_j = j + dj, again = true;
      }
    }
    const DisplayBox box = bounds(n, i, next_i).united(bounds(w, j, next_j));
    if (!box.empty()) boxes.push_back(box);
    i = next_i, j = next_j;
  }
}

std::optional<std::vector<DisplayBox>> DrawDamage::update(const ImDrawData& data) {
  resolved_.resize(static_cast<std::size_t>(std::max(data.CmdListsCount, 0)));
  for (int n = 0; n < data.CmdListsCount; ++n) resolve(*data.CmdLists[n], resolved_[static_cast<std::size_t>(n)]);
  const bool comparable = known_ && resolved_.size() == lists_.size();
  std::vector<DisplayBox> boxes;
  for (std::size_t n = 0; comparable && n < resolved_.size(); ++n) {
    const Resolved& now = resolved_[n];
    const Resolved& was = lists_[n];
    const bool same_commands = now.commands.size() == was.commands.size() &&
                               std::equal(now.commands.begin(), now.commands.end(), was.commands.begin(),
                                          [](const Command& a, const Command& b) { return a.same_as(b); });
    if (!same_commands) {
      compare({&now.triangles, 0, now.triangles.size()}, {&was.triangles, 0, was.triangles.size()}, boxes);
      continue;
    }
    for (std::size_t c = 0, now_from = 0, was_from = 0; c < now.commands.size(); ++c) {
      compare({&now.triangles, now_from, now.commands[c].end}, {&was.triangles, was_from, was.commands[c].end}, boxes);
      now_from = now.commands[c].end, was_from = was.commands[c].end;
    }
  }
  lists_.swap(resolved_);
  known_ = true;
  if (!comparable) return std::nullopt;
  return boxes;
}

}  // namespace ydscope::ui
