#include "app/gui/command_line_sources.h"

#include <cstdio>

#include "core/protocol/model_profile.h"

namespace ydscope::gui {
namespace {

// The Connection panel's model choice for a model name: 0 none, then all_profiles() order from 1.
int model_choice(const std::optional<std::string>& model, int none) {
  const ModelProfile* profile = model ? find_profile(*model) : nullptr;
  const auto profiles = all_profiles();
  for (std::size_t i = 0; i < profiles.size(); ++i)
    if (profile == &profiles[i]) return static_cast<int>(i) + 1;
  return none;
}

}  // namespace

ui::ConnectRequest connect_request_for(const SourceChoice& choice, const std::string& scene) {
  ui::ConnectRequest request;
  request.kind = choice.kind == SourceKind::Sim ? ui::ConnectRequest::Kind::Sim : ui::ConnectRequest::Kind::Port;
  request.address = choice.port;
  request.model = choice.model;
  request.baud = choice.baud;
  request.scene = choice.scene.empty() ? scene : choice.scene;
  return request;
}

ui::ConnectRequest command_line_request(const AppOptions& options, ui::PanelEdits& edits) {
  ui::ConnectRequest request;
  switch (options.source) {
    case SourceKind::Auto:  // never asked here (LidarSource::start_auto); a port is the nearest meaning
    case SourceKind::Port:
      request.kind = ui::ConnectRequest::Kind::Port;
      request.address = options.port;
      if (options.model && *options.model != "auto") request.model = options.model;
      if (options.baud) request.baud = *options.baud;
      std::snprintf(edits.port_text, sizeof edits.port_text, "%s", options.port.c_str());
      break;
    case SourceKind::Sim:
      request.kind = ui::ConnectRequest::Kind::Sim;
      request.model = options.model;
      request.scene = options.scene;
      edits.sim_model_choice = model_choice(options.model, edits.sim_model_choice);
      edits.sim_scene_choice = options.scene == "room" ? 0 : options.scene == "booth" ? 2 : 1;
      break;
    case SourceKind::Replay:
      request.kind = ui::ConnectRequest::Kind::Replay;
      request.address = options.replay_file;
      request.model = options.model;
      request.replay_speed = options.replay_speed;
      request.replay_loop = !options.replay_once;
      std::snprintf(edits.replay_text, sizeof edits.replay_text, "%s", options.replay_file.c_str());
      edits.replay_model_choice = model_choice(options.model, 0);  // the Replay tab shows the model it decodes as
      break;
  }
  return request;
}

}  // namespace ydscope::gui
