// App, carrying out what the user asked for this frame: each typed request from the panels, keys
// and mouse, in the order they came. Device commands go to the session with a callback that shows
// their outcome beside the control that asked; source, replay and virtual-lidar requests go to the
// LidarSource; view and file requests are done here.
#include <chrono>
#include <cstdio>
#include <type_traits>
#include <variant>

#include "app/gui/app.h"
#include "app/gui/screenshot.h"
#include "ui/panels/panels.h"
#include "ui/view/file_names.h"
#include "core/link/recording_control.h"
#include "ui/view/lap_csv.h"
#include "ui/view/lap_mcap.h"

namespace ydscope::gui {

void App::carry_out_requests(int framebuffer_width, int framebuffer_height) {
  // Taken first: carrying one out may not add to the list being walked.
  std::vector<ui::UiRequest> requests;
  requests.swap(model().requests);
  for (const ui::UiRequest& request : requests) carry_out(request, framebuffer_width, framebuffer_height);
  follow_replay();
}

void App::carry_out(const ui::UiRequest& request, int framebuffer_width, int framebuffer_height) {
  ui::UiModel& m = model();
  using ui::CommandControl;
  std::visit(
      [&](const auto& r) {
        using R = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<R, ui::ConnectRequest>) {
          if (r.kind == ui::ConnectRequest::Kind::Replay) settings_.last_replay_file = r.address;
          outputs_.leave_source(sel());
          source().stop();
          start_clean();
          m.banner.clear();
          start(r);
        } else if constexpr (std::is_same_v<R, ui::Disconnect>) {
          outputs_.leave_source(sel());
          source().stop();
          start_clean();
          sel().has_source = false;
          m.source_text.clear();
          m.banner.clear();
        } else if constexpr (std::is_same_v<R, ui::RefreshPorts>) {
          m.ports = discover_ports();
        } else if constexpr (std::is_same_v<R, ui::ControlReplay>) {
          if (!m.replay.available) return;
          ReplayHandle& replay = source().replay();
          replay.set_paused(r.paused);
          replay.set_speed(r.speed);
          replay.set_loop(r.loop);
        } else if constexpr (std::is_same_v<R, ui::SetSimFaults>) {
          if (SimServer* sim = source().sim()) sim->set_faults(r.faults);
        } else if constexpr (std::is_same_v<R, ui::UnplugSim>) {
          if (SimServer* sim = source().sim()) sim->unplug();
        } else if constexpr (std::is_same_v<R, ui::ReplugSim>) {
          if (SimServer* sim = source().sim()) sim->replug();
        } else if constexpr (std::is_same_v<R, ui::SetScanHz>) {
          session().set_scan_hz(r.hz, ui::track_command(m, CommandControl::ScanFrequency));
        } else if constexpr (std::is_same_v<R, ui::SetRangingKhz>) {
          session().set_ranging_khz(r.khz, ui::track_command(m, CommandControl::RangingFrequency));
        } else if constexpr (std::is_same_v<R, ui::RefreshHealth>) {
          session().refresh_health(ui::track_command(m, CommandControl::Health));
        } else if constexpr (std::is_same_v<R, ui::StartRecording>) {
          outputs_.start_recording(sel(), r);
        } else if constexpr (std::is_same_v<R, ui::StopRecording>) {
          outputs_.stop_recording(sel());
        } else if constexpr (std::is_same_v<R, ui::SetShare>) {
          if (r.on)
            outputs_.start_share(sel());
          else
            outputs_.stop_share(sel());
        } else if constexpr (std::is_same_v<R, ui::SetDistanceScale>) {
          session().set_distance_scale(r.mm_per_count);
        } else if constexpr (std::is_same_v<R, ui::ResetView>) {
          view_->reset(settings_);
        } else if constexpr (std::is_same_v<R, ui::SaveScreenshot>) {
          const std::string path = timestamped_name("png");
          const std::string error = save_framebuffer_png(path, framebuffer_width, framebuffer_height);
          m.status_message = error.empty() ? "saved " + path : error;
        } else if constexpr (std::is_same_v<R, ui::ExportLapCsv>) {
          if (history().empty()) {
            m.status_message = "no lap to export yet.";
            return;
          }
          // What is on screen, frozen or live: the view's laps, never a newer one it has not shown.
          const std::size_t laps = r.every_shown_lap ? history().size() : 1;
          const std::string path = timestamped_name("csv");
          const std::string error = save_text_file(path, ui::shown_laps_csv(history(), laps));
          m.status_message = error.empty() ? "exported " + shown_laps_words(laps) + " to " + path : error;
        } else if constexpr (std::is_same_v<R, ui::ExportLapMcap>) {
          export_shown_laps_mcap();
        } else if constexpr (std::is_same_v<R, ui::WatchSector>) {
          m.sector_error = ui::watch_sector(m.sectors, r.spec);
          if (!m.sector_error.empty()) return;
          edits().sector_text[0] = '\0';
          sync_sectors();
        } else if constexpr (std::is_same_v<R, ui::UnwatchSector>) {
          unwatch_sector(r.index);
        } else if constexpr (ui::is_source_list_request<R>) {
          change_sources(r);
        } else {
          static_assert(!sizeof(R), "a request the app does not carry out");
        }
      },
      request);
}

std::string App::shown_laps_words(std::size_t laps) const {
  const std::string what = laps == 1
                               ? "lap " + std::to_string(history().newest().index)
                               : std::to_string(laps) + " laps (" + std::to_string(history().at_age(laps - 1).index) +
                                     " to " + std::to_string(history().newest().index) + ")";
  return what + (model().paused_view ? " as frozen" : "");
}

void App::export_shown_laps_mcap() {
  ui::UiModel& m = model();
  if (history().empty()) {
    m.status_message = "no lap to export yet.";
    return;
  }
  const SessionSnapshot& s = m.snap;
  const Model model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  // The laps carry steady-clock receive times; the file wants wall-clock ones.
  const auto wall_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch());
  const auto steady =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch());
  const std::string path = timestamped_name("mcap");
  const ui::ShownLapsMcap saved = ui::save_shown_laps_mcap(
      history(), history().size(), model,
      recording_metadata_of(s, m.source_text, s.distance_scale > 0 ? std::optional(s.distance_scale) : std::nullopt),
      (wall_ns - steady).count(), path);
  m.status_message = saved.error.empty() ? "exported " + shown_laps_words(saved.laps) + " to " + path + " (" +
                                               std::to_string(saved.messages) + " messages on /scan and /points)"
                                         : saved.error;
}

void App::follow_replay() {
  ui::UiModel& m = model();
  if (!m.replay.available) return;
  if (const auto status = source().replay().status()) {
    m.replay.position_s = static_cast<double>(status->position_ns) * 1e-9;
    m.replay.duration_s = static_cast<double>(status->duration_ns) * 1e-9;
    m.replay.passes = status->loops;
    // The tab shows what the link does. Taken only when the link's value changes, so a slider
    // being dragged is not pulled back to the value the I/O thread has not caught up with.
    if (!sel().last_replay_status || sel().last_replay_status->speed != status->speed)
      m.replay.speed = static_cast<float>(status->speed);
    if (!sel().last_replay_status || sel().last_replay_status->loop != status->loop) m.replay.loop = status->loop;
    if (!sel().last_replay_status || sel().last_replay_status->paused != status->paused)
      m.replay.paused = status->paused;
    sel().last_replay_status = status;
  }
  // Without loop the session closes the link at the recording's end and does not reopen it.
  m.replay.ended = m.snap.state == LinkState::Failed && sel().last_lap_at.has_value();
}

}  // namespace ydscope::gui
