#include "app/gui/app_options.h"

#include "app/gui/app_help.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "app/common/source_list_options.h"
#include "core/analysis/sector.h"
#include "core/analysis/zone.h"
#include "core/protocol/model_profile.h"

namespace ydscope::gui {

const char* const kAppHelp = kAppHelpText;

namespace {

// --port more than once, or with --name/--pose; empty for a lone port as before.
std::vector<SourceChoice> several_ports(const Arguments& args) {
  if (args.values("port").size() < 2 && !args.has("name") && !args.has("pose")) return {};
  std::vector<SourceChoice> choices;
  for (const SourceText& text : source_texts_from(args)) {
    SourceChoice choice;
    choice.kind = SourceKind::Port;
    choice.port = text.port;
    if (text.model && *text.model != "auto") {
      if (!find_profile(*text.model))
        throw UsageError("unknown model '" + *text.model + "'; choose one of " + std::string(model_names()) + ".");
      choice.model = text.model;
    }
    if (text.baud && *text.baud != "auto") choice.baud = parse_baud_text(*text.baud);
    choice.name = text.name;
    choice.pose = text.pose;
    choice.serial = text.serial.value_or("");
    choices.push_back(std::move(choice));
  }
  return choices;
}

// --sim G1,G6,TG30: a virtual lidar of each; empty for a lone model as before.
std::vector<SourceChoice> several_sims(const std::string& models) {
  if (models.find(',') == std::string::npos) return {};
  std::vector<SourceChoice> choices;
  for (std::size_t start = 0; start <= models.size();) {
    const std::size_t comma = std::min(models.find(',', start), models.size());
    const std::string model = models.substr(start, comma - start);
    const ModelProfile* profile = find_profile(model);
    if (!profile)
      throw UsageError("--sim: unknown model '" + model + "'; list models from " + std::string(model_names()) +
                       " with commas, e.g. --sim G1,G6,TG30.");
    SourceChoice choice;
    choice.kind = SourceKind::Sim;
    choice.model = std::string(profile->name);
    choice.name = std::string(profile->name);
    choices.push_back(std::move(choice));
    start = comma + 1;
  }
  return choices;
}

}  // namespace

AppOptions parse_app_options(std::span<const std::string> raw) {
  const Arguments args(raw,
                       {"port", "sim", "replay", "model", "baud", "scene", "screenshot", "frames", "sector", "speed",
                        "share-port", "record", "name", "pose", "serial", "zone"},
                       {"fullscreen", "once", "share", "split", "zone-beep", "check"}, 0, [] {
                         auto repeatable = source_repeatable_options();
                         repeatable.insert("zone");
                         return repeatable;
                       }());
  AppOptions options;
  const bool port = args.has("port"), sim = args.has("sim"), replay = args.has("replay");
  if (int(port) + int(sim) + int(replay) > 1)
    throw UsageError("choose one source: --port, --sim or --replay, not more than one.");
  if (port) {
    options.source = SourceKind::Port;
    options.port = *args.value("port");
  } else if (sim) {
    options.source = SourceKind::Sim;
    options.model = args.value("sim");
    options.sources = several_sims(*options.model);
    if (!options.sources.empty()) options.model = options.sources.front().model;
  } else if (replay) {
    options.source = SourceKind::Replay;
    options.replay_file = *args.value("replay");
  }
  if (const auto model = args.value("model")) {
    if (sim) throw UsageError("--sim names the model already; drop --model.");
    options.model = model;
  }
  if (const auto baud = args.integer("baud", 50, 4'000'000)) options.baud = static_cast<unsigned>(*baud);
  options.scene = args.value("scene").value_or(options.scene);
  // The Replay tab's slider holds the same speeds, so the two never disagree.
  if (const auto speed = args.number("speed", 0.25, 8.0)) {
    if (!replay) throw UsageError("--speed goes with --replay FILE.");
    options.replay_speed = *speed;
  }
  options.replay_once = args.has("once");
  if (options.replay_once && !replay) throw UsageError("--once goes with --replay FILE.");
  options.fullscreen = args.has("fullscreen");
  options.screenshot_path = args.value("screenshot").value_or("");
  if (!options.screenshot_path.empty()) {
    // Said before the window opens, not after the frames it was asked to wait for.
    const std::filesystem::path folder = std::filesystem::path(options.screenshot_path).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
      throw UsageError("--screenshot: there is no folder " + folder.string() + " to save " + options.screenshot_path +
                       " in.");
  }
  if (const auto frames = args.integer("frames", 1, 1'000'000)) {
    if (options.screenshot_path.empty()) throw UsageError("--frames goes with --screenshot PNG.");
    options.frames = static_cast<int>(*frames);
  }
  for (const std::string& zone : args.values("zone")) {
    std::string error;
    if (!parse_zone(zone, error)) throw UsageError("--zone: " + error);
    options.zones.push_back(zone);
  }
  options.zone_beep = args.has("zone-beep");
  if (const auto sector = args.value("sector")) {
    std::string error;
    if (!parse_sector_spec(*sector, error)) throw UsageError("--sector: " + error);
    options.sector = sector;
  }
  options.record = args.value("record").value_or("");
  if (!options.record.empty() && options.record != "ydrec" && options.record != "mcap" && options.record != "both")
    throw UsageError("--record takes ydrec, mcap or both, not '" + options.record + "'.");
  options.share = args.has("share");
  options.check = args.has("check");
  if (const auto share_port = args.integer("share-port", 0, 65535))
    options.share_port = static_cast<std::uint16_t>(*share_port);
  if (options.model && !find_profile(*options.model) &&
      !(options.source == SourceKind::Port && *options.model == "auto")) {
    throw UsageError("unknown model '" + *options.model + "'; choose one of " + std::string(model_names()) + ".");
  }
  if (options.source == SourceKind::Auto && (options.model || options.baud)) {
    throw UsageError("--model and --baud go with --port (or --sim MODEL); see ydscope --help.");
  }
  for (const char* option : {"model", "baud"})  // once per port is for several ports
    if (args.values(option).size() > 1 && args.values("port").size() < 2)
      throw UsageError("--" + std::string(option) + " is given twice; give it once (or once per --port).");
  if ((args.has("name") || args.has("pose")) && !port)
    throw UsageError(
        "--name and --pose go with --port, once per port; name and place virtual lidars in the Sources panel.");
  if (port) options.sources = several_ports(args);
  options.split = args.has("split");
  if (options.split && options.sources.empty())
    throw UsageError(
        "--split puts several sources side by side; give --sim with several models or --port more than once.");
  return options;
}

}  // namespace ydscope::gui
