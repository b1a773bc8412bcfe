#pragma once
// Where the app's bytes come from: a port the user names, the first lidar found, the virtual lidar
// started in-process on a pseudo-terminal, or a recording. Whatever it is, the Session reads it
// through the same path a real serial port uses.
#include <memory>
#include <string>
#include <vector>

#include "app/gui/replay_source.h"
#include "core/session/session.h"
#include "core/sim/sim_server.h"
#include "ui/panels/ui_model.h"

namespace ydscope::gui {

class LidarSource {
 public:
  explicit LidarSource(Session& session) : session_(session) {}
  ~LidarSource();

  // Starts the request; on failure leaves the session idle and returns one sentence.
  std::string start(const ui::ConnectRequest& request);
  // No source named: the first lidar the port discovery finds, else the virtual G6 (demo scene).
  // Returns the banner to show. When a port was found, auto_probing() stays true until the app
  // sees laps or gives up and calls fall_back_to_sim().
  std::string start_auto();
  bool auto_probing() const { return auto_probing_; }
  void auto_probe_done() { auto_probing_ = false; }
  // The port named no lidar after all: stop it and show the virtual G6. Returns the banner.
  std::string fall_back_to_sim();
  void stop();

  std::string description() const { return description_; }
  // How the session was last connected (its port or the virtual lidar's, model, baud): what
  // Run check opens while the session lets the port go.
  const SessionConfig& config() const { return config_; }
  // What is wrong with the current source but does not stop it (a recording cut off at its end,
  // damaged record times or fields), one sentence each, in ydscope-cli's words.
  const std::vector<std::string>& warnings() const { return warnings_; }
  bool sim_active() const { return sim_ != nullptr; }
  SimServer* sim() { return sim_.get(); }
  bool replay_active() const { return replay_; }
  ReplayHandle& replay() { return *replay_handle_; }

 private:
  Session& session_;
  std::unique_ptr<SimServer> sim_;
  SessionConfig config_;
  std::string description_;
  std::vector<std::string> warnings_;
  bool replay_ = false;
  bool auto_probing_ = false;
  std::shared_ptr<ReplayHandle> replay_handle_ = std::make_shared<ReplayHandle>();
};

// Candidate serial ports with their USB names, for the Connection panel.
std::vector<ui::PortEntry> discover_ports();

}  // namespace ydscope::gui
