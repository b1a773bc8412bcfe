#pragma once
// What settings.ini remembers of the lidars across runs: each one's look by name (where it sits
// and its colour, up to 32 names), and the names of the last run's lidars when it had several.
#include <string>
#include <vector>

#include "ui/view/settings/settings.h"
#include "ui/view/scene/source_set.h"

namespace ydscope::ui {

// A source named as a remembered one gets its pose back (unless `pose_given`) and its colour,
// unless one of `others` (the other sources now running) has that colour: two never share one.
void recall_look(const ViewSettings& settings, const std::vector<SourceLook>& others, SourceLook& look,
                 bool pose_given);

// At the end of a run of `looks`: with several, each is remembered as it is now, shown and live,
// and their names become the last run's; a lone lidar is drawn round itself and leaves nothing.
void remember_looks(ViewSettings& settings, const std::vector<SourceLook>& looks);

// The remembered source `name` bound to the unit of `serial` (its `unit = SERIAL; NAME` line),
// and no other source to it: a unit has one name.
void bind_serial(std::vector<SourceLook>& remembered, const std::string& name, const std::string& serial);

}  // namespace ydscope::ui
