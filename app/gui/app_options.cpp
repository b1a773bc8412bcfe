#include "app/gui/app_options.h"

#include <charconv>

#include "app/gui/app_help.h"
#include "core/protocol/model_profile.h"

namespace ydscope::gui {

const char* const kAppHelp = kAppHelpText;

namespace {

const std::string& value_of(std::span<const std::string> args, std::size_t& i) {
  if (i + 1 >= args.size()) throw OptionsError(args[i] + " needs a value; see ydscope --help.");
  return args[++i];
}

void set_source(AppOptions& options, SourceKind kind, const std::string& flag) {
  if (options.source != SourceKind::Auto && options.source != kind) {
    throw OptionsError("choose one source: --port, --sim or --replay (" + flag + " came after another).");
  }
  options.source = kind;
}

}  // namespace

AppOptions parse_app_options(std::span<const std::string> args) {
  AppOptions options;
  bool frames_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-h" || a == "--help") {
      options.help = true;
    } else if (a == "-V" || a == "--version") {
      options.version = true;
    } else if (a == "--port") {
      set_source(options, SourceKind::Port, a);
      options.port = value_of(args, i);
    } else if (a == "--sim") {
      set_source(options, SourceKind::Sim, a);
      options.model = value_of(args, i);
    } else if (a == "--replay") {
      set_source(options, SourceKind::Replay, a);
      options.replay_file = value_of(args, i);
    } else if (a == "--model") {
      options.model = value_of(args, i);
    } else if (a == "--scene") {
      options.scene = value_of(args, i);
    } else if (a == "--baud") {
      const std::string& v = value_of(args, i);
      unsigned baud = 0;
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), baud);
      if (ec != std::errc{} || end != v.data() + v.size() || baud == 0) {
        throw OptionsError("--baud takes a positive number such as 230400 or 512000, not '" + v + "'.");
      }
      options.baud = baud;
    } else if (a == "--fullscreen") {
      options.fullscreen = true;
    } else if (a == "--screenshot") {
      options.screenshot_path = value_of(args, i);
    } else if (a == "--frames") {
      const std::string& v = value_of(args, i);
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), options.frames);
      if (ec != std::errc{} || end != v.data() + v.size() || options.frames < 1) {
        throw OptionsError("--frames takes a positive number of frames, not '" + v + "'.");
      }
      frames_given = true;
    } else {
      throw OptionsError("unknown option '" + a + "'; see ydscope --help.");
    }
  }
  if (options.model && !find_profile(*options.model) && !(options.source == SourceKind::Port && *options.model == "auto")) {
    throw OptionsError("unknown model '" + *options.model + "'; choose one of " + std::string(model_names()) + ".");
  }
  if (options.source == SourceKind::Auto && (options.model || options.baud)) {
    throw OptionsError("--model and --baud go with --port (or --sim MODEL); see ydscope --help.");
  }
  if (frames_given && options.screenshot_path.empty()) {
    throw OptionsError("--frames goes with --screenshot PNG.");
  }
  return options;
}

}  // namespace ydscope::gui
