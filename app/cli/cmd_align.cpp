// ydscope-cli align: where each of several lidars sits relative to the first (the reference), by
// matching several laps of each against the reference's walls (core/align). Prints the poses as
// --pose and as the source list spells them; --apply keeps them where the app looks them up.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/cli_command.h"
#include "app/cli/remembered_poses.h"
#include "app/cli/session_cli.h"
#include "app/cli/units_by_serial.h"
#include "app/common/arguments.h"
#include "app/common/lap_bell.h"
#include "app/common/source_list_options.h"
#include "core/align/align.h"
#include "core/frame/unit_identity.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kAlignHelp =
    R"(usage: ydscope-cli align --port A [--name N] [--serial S] [--pose X,Y,YAW[,flip]] --port B [--name N] ...
                         [--laps N] [--apply] [--model M] [--baud B] [--conventions field|manual]

Finds where each lidar sits relative to the first --port (the reference), from the walls they both
see: N laps of each (default 10) are folded into their steady points (people walking and a
mirror's ghosts drop out), a correlative search within 45 degrees and 1 m of each lidar's start
finds candidates, and point-to-line ICP with trimmed pairs refines them (docs/align.md).

A lidar's start is its --pose, else the pose remembered for its --name (what --apply writes),
else the origin. The reference keeps its pose; the others' poses are in its frame. A name bound to
a unit's serial (--serial, or by an earlier --apply) follows that unit to whatever port it
answers on, and a swap is said (docs/identity.md).

For each lidar it prints the pose, the residual (RMS distance of its points to the reference's
walls, mm) and the overlap (its steady points on those walls), or "not enough overlap" with the
numbers when the walls they share do not pin the pose down; then the whole source list with the
poses found, to paste after `ydscope-cli record`, `serve` or `ydscope`.

  --laps N      laps of each lidar to match (2..200, default 10).
  --apply       keep the poses found under each --name in the app's settings.ini (where `ydscope`
                looks up a lidar's pose by its name), each name bound to its unit's serial;
                nothing is written for a lidar that was not aligned.

Exit status: 0 every lidar aligned; 1 a lidar could not be read; 2 usage error; 3 some lidar was
not aligned (the others are printed, and applied with --apply).

example:
  ydscope-cli align --port /dev/ydlidar-front --name front --port /dev/ydlidar-rear --name rear \
      --pose -0.4,0,180 --apply
)";

struct Lidar {
  SourceText text;
  Pose start;
  std::unique_ptr<Session> session;
  std::vector<Lap> laps;
  std::string serial;  // as its unit answered A5 90
};

// Names and starts follow the units' serials (--serial, or settings.ini's unit lines) to the ports
// they answered on; the laps stay with their port. Each move or swap is said on stderr.
void follow_serials(std::vector<Lidar>& lidars) {
  std::vector<SourceInfo> given;
  std::vector<UnitSeen> seen;
  for (Lidar& lidar : lidars) {
    given.push_back({lidar.text.name, lidar.start, std::nullopt, "", lidar.text.serial.value_or("")});
    const SessionSnapshot s = lidar.session->snapshot();
    lidar.serial = s.device ? s.device->serial : std::string();
    seen.push_back({lidar.text.port, lidar.serial});
  }
  recall_serials(given);
  const UnitIdentity identity = identify_units(given, seen);
  // A serial two units share (virtual lidars of one seed) names neither: it is not bound or printed.
  for (Lidar& lidar : lidars)
    if (std::count_if(seen.begin(), seen.end(), [&](const UnitSeen& u) { return u.serial == lidar.serial; }) > 1)
      lidar.serial.clear();
  for (std::size_t i = 0; i < lidars.size(); ++i) {
    lidars[i].text.name = identity.sources[i].name;
    lidars[i].start = identity.sources[i].pose;
  }
  for (const std::string& note : identity.notes) std::fprintf(stderr, "ydscope-cli align: %s\n", note.c_str());
}

// Every lidar scanning, then `wanted` laps of each (the first one dropped: it may have begun
// before the motor settled). Throws std::runtime_error when one stops.
void gather(std::vector<Lidar>& lidars, std::size_t wanted, LapBell& bell) {
  Lap lap;
  std::vector<bool> first_seen(lidars.size(), false);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20 + wanted);
  for (;;) {
    bool all = true;
    for (std::size_t i = 0; i < lidars.size(); ++i) {
      Lidar& lidar = lidars[i];
      while (lidar.laps.size() < wanted && lidar.session->laps().try_pop(lap)) {
        if (!first_seen[i]) {
          first_seen[i] = true;
          continue;
        }
        lidar.laps.push_back(lap);
      }
      all = all && lidar.laps.size() >= wanted;
      const SessionSnapshot s = lidar.session->snapshot();
      if (s.state == LinkState::Failed)
        throw std::runtime_error(lidar.text.port + ": " + (s.message.empty() ? describe_snapshot(s) : s.message));
    }
    if (all) return;
    if (end_requested().load()) throw std::runtime_error("interrupted before every lidar gave its laps");
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error("not every lidar gave " + std::to_string(wanted) + " laps in time");
    bell.wait(std::chrono::milliseconds(200));
  }
}

int run_align(std::span<const std::string> raw) {
  const Arguments args(raw, session_value_options({"laps", "name", "pose", "serial"}), {"apply"}, 0,
                       source_repeatable_options());
  const auto laps_wanted = static_cast<std::size_t>(args.integer("laps", 2, 200).value_or(10));
  std::vector<SourceText> texts = source_texts_from(args);
  if (texts.size() < 2) throw UsageError("align needs two or more lidars: give --port once for each");
  const std::filesystem::path settings_file = remembered_poses_file();

  LapBell bell;
  std::vector<Lidar> lidars;
  std::vector<SessionConfig> configs;
  for (SourceText& text : texts) {
    configs.push_back(session_config_for(text.port, text.model, text.baud, /*scan=*/true));
    configs.back().reading = reading_option(args);
    Lidar lidar;
    lidar.start = text.pose ? *text.pose : remembered_pose(settings_file, text.name).value_or(Pose{});
    lidar.text = std::move(text);
    lidars.push_back(std::move(lidar));
  }
  {
    EndSignalsStayHere signals_here;  // the sessions' threads leave Ctrl-C to this one
    for (Lidar& lidar : lidars) lidar.session = std::make_unique<Session>(laps_wanted + 4, [&bell] { bell.ring(); });
  }
  end_on_signals();
  for (std::size_t i = 0; i < lidars.size(); ++i) connect_or_throw(*lidars[i].session, configs[i]);
  std::fprintf(stderr, "ydscope-cli align: gathering %zu laps of each of %zu lidars\n", laps_wanted, lidars.size());
  gather(lidars, laps_wanted, bell);
  for (Lidar& lidar : lidars) lidar.session->disconnect();
  follow_serials(lidars);

  const Lidar& reference = lidars.front();
  std::printf("%s: reference, pose %s\n", reference.text.name.c_str(), format_pose(reference.start).c_str());
  std::vector<NamedPose> found{{reference.text.name, reference.start, reference.serial}};
  std::vector<Pose> shown{reference.start};
  bool all_aligned = true;
  for (std::size_t i = 1; i < lidars.size(); ++i) {
    const Lidar& lidar = lidars[i];
    const align::AlignResult r = align::align_to_reference(reference.laps, reference.start, lidar.laps, lidar.start);
    if (r.verdict == align::AlignVerdict::Aligned) {
      const Pose pose = align::reported_pose(r.pose);
      std::printf("%s: --pose %s (%s)\n", lidar.text.name.c_str(), format_pose(pose).c_str(), r.message.c_str());
      found.push_back({lidar.text.name, pose, lidar.serial});
      shown.push_back(pose);
    } else {
      std::printf("%s: %s; its pose stays %s\n", lidar.text.name.c_str(), r.message.c_str(),
                  format_pose(lidar.start).c_str());
      shown.push_back(lidar.start);
      all_aligned = false;
    }
  }
  std::string list;
  for (std::size_t i = 0; i < lidars.size(); ++i)
    list += (i ? " " : "") + std::string("--port ") + lidars[i].text.port + " --name " + lidars[i].text.name +
            (lidars[i].serial.empty() ? "" : " --serial " + lidars[i].serial) + " --pose " + format_pose(shown[i]);
  std::printf("source list: %s\n", list.c_str());
  if (args.has("apply")) {
    std::string error;
    if (!remember_poses(settings_file, found, error)) throw std::runtime_error(error);
    std::printf("applied: %zu poses kept in %s\n", found.size(), settings_file.string().c_str());
  }
  std::fflush(stdout);
  return all_aligned ? kExitOk : kExitLidarFault;
}

const RegisterCliCommand align_command{
    {"align", "find where several lidars sit from the walls they share", kAlignHelp, run_align}};

}  // namespace
}  // namespace ydscope::cli
