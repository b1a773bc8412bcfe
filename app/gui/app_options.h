#pragma once
// The command line of `ydscope`: which source to show and the screenshot mode used by CI.
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace ydscope::gui {

enum class SourceKind { Auto, Port, Sim, Replay };

struct AppOptions {
  SourceKind source = SourceKind::Auto;
  std::string port;                  // --port PATH or tcp://host:port
  std::optional<std::string> model;  // --model (port: fixed model instead of auto; sim: the model)
  std::optional<unsigned> baud;      // --baud
  std::string scene = "demo";        // --scene for --sim
  std::string replay_file;           // --replay FILE
  bool fullscreen = false;
  std::string screenshot_path;       // --screenshot PNG
  int frames = 120;                  // --frames N with --screenshot
  bool help = false;
  bool version = false;
};

class OptionsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws OptionsError with one sentence for a bad command line.
AppOptions parse_app_options(std::span<const std::string> args);
extern const char* const kAppHelp;

}  // namespace ydscope::gui
