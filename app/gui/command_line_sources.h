#pragma once
// The sources the app's command line names, as the requests that start them.
#include <string>

#include "app/gui/app_options.h"
#include "ui/panels/panel_edits.h"
#include "ui/panels/ui_request.h"

namespace ydscope::gui {

// One of several lidars (--sim G1,G6 or several --port); `scene` where the choice names none.
ui::ConnectRequest connect_request_for(const SourceChoice& choice, const std::string& scene);
// The lone source of --port, --sim or --replay (not the automatic choice). The Connection
// panel's tab for it is filled in to show what runs, so Connect there starts it again.
ui::ConnectRequest command_line_request(const AppOptions& options, ui::PanelEdits& edits);

}  // namespace ydscope::gui
