#include "app/gui/lidar_source.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "core/link/port_discovery.h"
#include "core/protocol/model_profile.h"

namespace ydscope::gui {
namespace {

// The virtual lidar's pty gets a stable symlink, so the session can reopen it after an unplug
// (a replug makes a new /dev/pts/N and re-points the link).
std::string sim_link_path() {
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  const std::filesystem::path dir = runtime && *runtime ? runtime : std::filesystem::temp_directory_path().string();
  // Several virtual lidars in one app each get their own: the first keeps the plain name.
  static std::atomic<int> started{0};
  const int n = started++;
  const std::string suffix = n == 0 ? std::string() : "-" + std::to_string(n + 1);
  return (dir / ("ydscope-sim-" + std::to_string(getpid()) + suffix)).string();
}

}  // namespace

LidarSource::~LidarSource() { stop(); }

void LidarSource::stop() {
  session_.disconnect();
  if (sim_) {
    sim_->stop();
    sim_.reset();
  }
  replay_ = false;
  description_.clear();
  warnings_.clear();
}

std::string LidarSource::start(const ui::ConnectRequest& request) {
  stop();
  SessionConfig config;
  switch (request.kind) {
    case ui::ConnectRequest::Kind::Port: {
      config.address = request.address;
      if (request.model) {
        const ModelProfile* profile = find_profile(*request.model);
        if (!profile) return "unknown model " + *request.model + "; choose one of " + std::string(model_names()) + ".";
        config.model = profile->model;
      }
      config.baud = request.baud;
      // Without a fixed model or baud, find the baud by asking for device info at each candidate.
      config.probe_baud = !request.model && !request.baud;
      description_ = request.address;
      break;
    }
    case ui::ConnectRequest::Kind::Sim: {
      const ModelProfile* profile = find_profile(request.model.value_or("G6"));
      if (!profile)
        return "unknown model " + request.model.value_or("") + "; choose one of " + std::string(model_names()) + ".";
      SimServerOptions options;
      options.device.model = profile->model;
      options.device.scene = request.scene;
      options.device.faults = request.faults;
      options.device.seed = 7;
      options.device.unit = request.sim_unit;
      options.device.host_compat = request.host_compat;
      options.device.firmware_major = request.firmware_major;
      options.device.firmware_minor = request.firmware_minor;
      options.delivery = request.delivery;
      options.transport = SimTransport::Pty;
      options.pty_link = sim_link_path();
      try {
        sim_ = std::make_unique<SimServer>(options);
        sim_->start();
      } catch (const std::exception& e) {
        sim_.reset();
        return std::string("the virtual lidar did not start: ") + e.what();
      }
      config.address = sim_->link_path().empty() ? sim_->device_path() : sim_->link_path();
      config.model = profile->model;
      description_ = "virtual " + std::string(profile->name) + " (" + request.scene + " scene";
      if (request.host_compat != HostCompat::Manual)
        description_ += ", " + std::string(host_compat_name(request.host_compat)) + " host";
      if (request.delivery.kind != DeliveryKind::Whole) description_ += ", delivery " + delivery_text(request.delivery);
      description_ += ") on " + sim_->device_path();
      break;
    }
    case ui::ConnectRequest::Kind::Replay: {
      std::string error;
      replay_handle_ = std::make_shared<ReplayHandle>();
      ReplayOptions options;
      options.speed = request.replay_speed;
      options.loop = request.replay_loop;
      auto replay = replay_config(request.address, request.model, options, replay_handle_, error, warnings_);
      if (!replay) return error;
      config = std::move(*replay);
      replay_ = true;
      description_ = "recording " + std::filesystem::path(request.address).filename().string();
      break;
    }
  }
  config_ = config;
  session_.connect(config);
  return {};
}

std::string LidarSource::start_auto() {
  // Known lidar USB bridges come first; the app watches whether laps arrive (see auto_probing).
  if (const auto candidate = first_lidar_candidate(PortDiscovery().list())) {
    ui::ConnectRequest request;
    request.kind = ui::ConnectRequest::Kind::Port;
    request.address = candidate->preferred_path();
    if (start(request).empty()) {
      auto_probing_ = true;
      return "Looking for a lidar on " + request.address + "\xE2\x80\xA6";
    }
  }
  return fall_back_to_sim();
}

std::string LidarSource::fall_back_to_sim() {
  const std::string tried = auto_probing_ ? description_ : std::string();
  auto_probing_ = false;
  ui::ConnectRequest sim;
  sim.kind = ui::ConnectRequest::Kind::Sim;
  sim.model = "G6";
  sim.scene = "demo";
  const std::string error = start(sim);
  if (!error.empty()) return "No lidar found, and " + error;
  if (!tried.empty()) return "No lidar answered on " + tried + " \xE2\x80\x94 showing the virtual G6 (demo scene)";
  return "No lidar found \xE2\x80\x94 showing the virtual G6 (demo scene)";
}

std::vector<ui::PortEntry> discover_ports() {
  std::vector<ui::PortEntry> entries;
  for (const SerialPortInfo& port : PortDiscovery().list()) {
    std::string label = port.preferred_path();
    if (const std::string what = port.description(); !what.empty()) label += " \xE2\x80\x94 " + what;
    entries.push_back({port.preferred_path(), label});
  }
  return entries;
}

}  // namespace ydscope::gui
