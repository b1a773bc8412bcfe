// The View tab's Zones section: each zone's rule and state in words (the view colours the same:
// red while its rule is raised), and whether a raised zone rings the bell.
#include "ui/panels/panels.h"

namespace ydscope::ui {

void draw_zones_panel(UiModel& m, ViewSettings& v) {
  if (!ImGui::CollapsingHeader("Zones")) return;
  const ZoneWatch& watch = m.zones;
  if (watch.zones().empty()) {
    ImGui::TextDisabled("none: --zone NAME:sector:FROM:TO[:MIN:MAX] or zone = ... in settings.ini");
    return;
  }
  for (std::size_t z = 0; z < watch.zones().size(); ++z) {
    const Zone& zone = watch.zones()[z];
    const ZoneState& s = watch.states()[z];
    const ImVec4 colour = s.raised ? ImVec4{1.0f, 0.45f, 0.4f, 1.0f} : ImVec4{0.55f, 0.9f, 0.85f, 1.0f};
    ImGui::TextColored(colour, "%s", describe_zone(zone, s, watch.newest_ns()).c_str());
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s\nrule: %s; entries so far: %llu", zone_spec(zone).c_str(),
                        zone.rule == ZoneRule::Enter ? "raised while something is in it" : "raised while it is empty",
                        static_cast<unsigned long long>(s.entries));
  }
  ImGui::Checkbox("beep when a zone is raised", &v.zone_beep);
}

}  // namespace ydscope::ui
