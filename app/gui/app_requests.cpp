// App, carrying out what the user asked for this frame: each typed request from the panels, keys
// and mouse, in the order they came. What concerns one source's device, replay or virtual lidar
// goes to its SourceSlot; the source list, Share and Record, the view and files are done here.
#include <type_traits>
#include <variant>

#include "app/gui/app.h"
#include "app/gui/screenshot.h"
#include "app/gui/shown_laps_export.h"
#include "ui/panels/panels.h"

namespace ydscope::gui {

void App::carry_out_requests(int framebuffer_width, int framebuffer_height) {
  // Taken first: carrying one out may not add to the list being walked.
  std::vector<ui::UiRequest> requests;
  requests.swap(model().requests);
  for (const ui::UiRequest& request : requests) carry_out(request, framebuffer_width, framebuffer_height);
  sel().follow_replay();
}

void App::carry_out(const ui::UiRequest& request, int framebuffer_width, int framebuffer_height) {
  ui::UiModel& m = model();
  std::visit(
      [&](const auto& r) {
        using R = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<R, ui::ConnectRequest>) {
          if (r.kind == ui::ConnectRequest::Kind::Replay) settings_.last_replay_file = r.address;
          leave_source();
          m.banner.clear();
          sel().start(r);
        } else if constexpr (std::is_same_v<R, ui::Disconnect>) {
          leave_source();
          sel().has_source = false;
          m.source_text.clear();
          m.banner.clear();
        } else if constexpr (std::is_same_v<R, ui::RefreshPorts>) {
          m.ports = discover_ports();
        } else if constexpr (ui::is_device_request<R>) {
          sel().carry_out(r);
        } else if constexpr (std::is_same_v<R, ui::StartRecording>) {
          outputs_.start_recording(sources_, r);
        } else if constexpr (std::is_same_v<R, ui::StopRecording>) {
          outputs_.stop_recording(sources_);
        } else if constexpr (std::is_same_v<R, ui::SetShare>) {
          if (r.on)
            outputs_.start_share(sources_);
          else
            outputs_.stop_share(sources_);
        } else if constexpr (std::is_same_v<R, ui::ResetView>) {
          stage_.view().reset(settings_);
        } else if constexpr (std::is_same_v<R, ui::SaveScreenshot>) {
          const std::string path = timestamped_name("png");
          const std::string error = save_framebuffer_png(path, framebuffer_width, framebuffer_height);
          m.status_message = error.empty() ? "saved " + path : error;
        } else if constexpr (std::is_same_v<R, ui::ExportLapCsv>) {
          const std::size_t laps = r.every_shown_lap ? sel().history.size() : 1;
          m.status_message = export_shown_laps_csv(sel().history, laps, m.paused_view);
        } else if constexpr (std::is_same_v<R, ui::ExportLapMcap>) {
          m.status_message = export_shown_laps_mcap(sel().history, m.snap, m.source_text, m.paused_view);
        } else if constexpr (std::is_same_v<R, ui::WatchSector>) {
          m.sector_error = ui::watch_sector(m.sectors, r.spec);
          if (!m.sector_error.empty()) return;
          sel().edits.sector_text[0] = '\0';
          sync_sectors();
        } else if constexpr (std::is_same_v<R, ui::UnwatchSector>) {
          if (r.index >= m.sectors.size()) return;
          m.sectors.erase(m.sectors.begin() + static_cast<std::ptrdiff_t>(r.index));
          sync_sectors();
        } else if constexpr (ui::is_source_list_request<R>) {
          change_sources(r);
        } else {
          static_assert(!sizeof(R), "a request the app does not carry out");
        }
      },
      request);
}

}  // namespace ydscope::gui
