#pragma once
// How one of the app's sources was started, as one line of text settings.ini keeps with its look,
// so that a run with no source named starts the last run's lidars again:
//   "sim MODEL SCENE"            a virtual lidar ("sim G6 demo")
//   "port MODEL|detect ADDRESS"  a serial port or tcp:// bridge ("port detect /dev/ttyUSB0")
// A replay has none: a recording is looked at, not restarted unasked.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/gui/app_options.h"
#include "ui/panels/ui_request.h"
#include "ui/view/settings/settings.h"

namespace ydscope::gui {

// Empty for a replay.
std::string origin_of(const ui::ConnectRequest& request);
// The choice that starts it again (no name or pose yet); empty when the text is not an origin.
std::optional<SourceChoice> choice_from_origin(std::string_view origin);
// The last run's lidars, in its order, each with its name and pose, from settings.ini: those
// whose look is remembered with an origin. Fewer than two: nothing (one lidar is the usual start).
std::vector<SourceChoice> last_run_choices(const ui::ViewSettings& settings);

}  // namespace ydscope::gui
