#pragma once
// The command line of `ydscope`: which source to show and the screenshot mode used by CI.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "core/frame/pose.h"

namespace ydscope::gui {

enum class SourceKind { Auto, Port, Sim, Replay };

// One of several sources started together (--sim G1,G6,TG30, or --port given more than once, or
// with --name/--pose).
struct SourceChoice {
  SourceKind kind = SourceKind::Port;  // Port or Sim
  std::string port;
  std::optional<std::string> model;  // Port: fixed model (empty: detect); Sim: the model
  std::optional<unsigned> baud;
  std::string name;          // empty: the model's name, or lidar0, lidar1, ...
  std::optional<Pose> pose;  // empty: a spread that keeps the clouds apart
  std::string scene;         // Sim: its scene (empty: --scene's)
  std::string serial;        // --serial: the unit this name and pose belong to (empty: bound by port)
};

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
  std::string screenshot_path;        // --screenshot PNG
  int frames = 120;                   // --frames N with --screenshot
  std::optional<std::string> sector;  // --sector "FROM:TO [MIN:MAX]": watch it from the start
  std::vector<std::string> zones;     // --zone SPEC, repeatable (core/analysis/zone.h)
  bool zone_beep = false;             // --zone-beep: ring the bell when a zone's rule is raised
  std::string record;                 // --record ydrec|mcap|both: record from the start (timestamped names)
  bool share = false;                 // --share: serve the source to Foxglove from the start
  std::uint16_t share_port = 8765;    // --share-port N: where Share listens (127.0.0.1; 0 a free port)
  bool split = false;                 // --split: several sources side by side (View > split)
  bool check = false;                 // --check: Run check on the lidar at the start (Lidar > Check)
  std::vector<SourceChoice> sources;  // several at once (then they, not the fields above, are the source)
};

// Throws UsageError (the shared parser's, app/common/arguments.h) with one sentence for a bad command line.
AppOptions parse_app_options(std::span<const std::string> args);
extern const char* const kAppHelp;

}  // namespace ydscope::gui
