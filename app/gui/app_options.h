#pragma once
// The command line of `ydscope`: which source to show and the screenshot mode used by CI.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "app/common/arguments.h"

namespace ydscope::gui {

enum class SourceKind { Auto, Port, Sim, Replay };

struct AppOptions {
  SourceKind source = SourceKind::Auto;
  std::string port;                  // --port PATH or tcp://host:port
  std::optional<std::string> model;  // --model (port: fixed model instead of auto; sim: the model)
  std::optional<unsigned> baud;      // --baud
  std::string scene = "demo";        // --scene for --sim
  std::string replay_file;           // --replay FILE
  double replay_speed = 1.0;         // --speed X with --replay
  bool replay_once = false;          // --once with --replay: stop at the end instead of looping
  bool fullscreen = false;
  std::string screenshot_path;       // --screenshot PNG
  int frames = 120;                  // --frames N with --screenshot
  std::optional<std::string> sector; // --sector "FROM:TO [MIN:MAX]": watch it from the start
  std::string record;                // --record ydrec|mcap|both: record from the start (timestamped names)
  bool share = false;                // --share: serve the source to Foxglove from the start
  std::uint16_t share_port = 8765;   // --share-port N: where Share listens (127.0.0.1; 0 a free port)
};

// Throws UsageError (the shared parser's, app/common/arguments.h) with one sentence for a bad command line.
AppOptions parse_app_options(std::span<const std::string> args);
extern const char* const kAppHelp;

}  // namespace ydscope::gui
