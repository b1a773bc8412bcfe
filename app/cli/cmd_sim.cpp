// ydscope-cli sim: a virtual G1/G6/TG lidar on a pseudo-terminal or a TCP port, until SIGINT/SIGTERM.
#include <signal.h>

#include <cctype>
#include <charconv>
#include <chrono>
#include <iostream>
#include <stdexcept>
#include <string>

#include "app/cli/session_cli.h"
#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "core/analysis/sector.h"
#include "core/frame/pose.h"
#include "core/protocol/model_profile.h"
#include "core/sim/delivery.h"
#include "core/sim/host_compat.h"
#include "core/sim/scene.h"
#include "core/sim/sim_server.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kSimHelp =
    R"(usage: ydscope-cli sim --model MODEL (--pty LINK | --tcp HOST:PORT) [--scene room|demo|booth] [--pose X,Y,YAW]
                       [--seed N] [--serial S] [--host-compat manual|ydlidar-sdk] [--firmware MAJOR.MINOR]
                       [--delivery whole|burst:BYTES:US|random:MAX] [fault options] [--verbose]

Runs a virtual lidar that a host cannot tell from a real one by its bytes: it answers every command
of the model's manual, streams scan packets paced to real time and to the model's baud (G1 230400,
G6/TG 512000), and can inject faults. It serves until SIGINT or SIGTERM, then exits 0.

  --model MODEL          G1, G6, TG15, TG30 or TG50 (any letter case).
  --pty LINK             create a pseudo-terminal, make LINK a symlink to its device path, print
                         "ready <device path>" on stdout, and remove LINK on exit. LINK must not
                         exist (a dangling link into /dev/pts left by an earlier run is replaced).
                         Open LINK like a serial port; the baud you set does not matter.
  --tcp HOST:PORT        listen on HOST:PORT instead (e.g. 127.0.0.1:2000; port 0 picks one) and
                         print "ready tcp://HOST:PORT". One host at a time; others are turned away.
  --scene NAME           room: walls, furniture, two people walking, a mirror (G1 flag 2) and a
                         sunlit window (G1 flag 3). demo (default): a turning flower, orbiting
                         moons and a star-shaped wall, made to look good on a trade-show screen.
                         booth: a stand facing an aisle where visitors walk past (the app's
                         motion highlighting paints them hot).
  --pose X,Y,YAW[,flip]  stand somewhere else in the scene (room and booth): where a lidar at the
                         scene's origin would see it, as --pose of record and align spells it
                         (metres, degrees). Two virtual lidars, one posed, see the same walls from
                         two places; `ydscope-cli align` should find this pose.
  --seed N               seed of the scene's noise and motion, the serial number and every fault
                         decision (default 1). The same seed gives the same bytes.
  --serial S             the serial number A5 90 reports: 16 characters 0-9 or A-F (default: made
                         from --seed). Two virtual lidars with two serials are two units that
                         ydscope tells apart by serial, whatever port each is on.
  --distance-scale X     encode ranges with X mm per raw unit instead of the manual's (G1 1,
                         G6 0.25, TG 0.5), like vendor firmware variants.
  --conventions C        field (default): emit what a real unit of the model and firmware emits
                         (G6 S/2 mm at 18 k samples/s, TG S mm at 20 k, TG's byte before the zero
                         packet); manual: the manual's literal reading
  --health-quirk         answer only the other health command (A5 91 <-> A5 92), as some units do.
  --host-compat NAME     manual (default): answer exactly what the model's manual lists.
                         ydlidar-sdk: also answer what YDLIDAR's SDK (1.2.19, and its ROS 2 driver)
                         asks beyond the manual, so it starts without its 1-2 s timeouts: A5 92
                         health on G6/TG, A5 93 zero-offset angle (0), A5 00 silently, a
                         device-info frame after the scan header; TG reports its scan rate 0.4 Hz
                         high, as the SDK expects. The manual's answers are unchanged.
  --firmware MAJOR.MINOR firmware the device info reports (default 1.2), in the manual's byte order
                         (low byte major). YDLidar-SDK reads the bytes the other way round, and on
                         TG picks its distance scale from them: --firmware 1.1 or 2.0 takes its
                         "old firmware" path (S/2 mm, the manual's), 1.2 and above raw S mm.
                         G1: major 0..3, minor 0..31 (its CT carries them too).
  --delivery MODEL       how bytes reach the host, as a USB-serial bridge delivers them:
                         whole (default): as soon as the line has carried them (a read sees whole
                         replies and packets when the host keeps up); burst:BYTES:US: BYTES at a
                         time every US microseconds, a short rest after one quiet interval (a
                         CP210x/CH340 latency timer, e.g. burst:64:1000); random:MAX: writes of
                         1..MAX bytes at line rate, split anywhere (seeded by --seed).
  --verbose              print the commands received and the mode changes on stderr.
  --zero-log FILE        append "<n> <CLOCK_MONOTONIC ns>" to FILE just after each zero packet's
                         last byte is written (for latency measurements).

Faults (all off by default; every injected fault is counted):
  --corrupt RATE         flip one bit of a scan packet's sample byte with probability RATE per
                         byte (0..1): the packet fails its checksum on the host.
  --drop RATE            lose each outgoing byte (packets and replies) with probability RATE.
  --lose-packets RATE    never send a non-zero scan packet, with probability RATE per packet (on
                         G1 the lap's CRC8 check then fails on the host).
  --stall-ms N           stop sending for N ms (packets and replies due then are lost) ...
  --stall-every-ms M     ... every M ms of scanning (both needed; N < M).
  --health-bits N        raise health bits (0..255): G1 status bits in A5 92 and in CT; G6/TG
                         A5 91 status 2 (error) with N as the error code.
  --junk N               send N junk bytes in front of every reply header.
  --scan-offset-hz F     a motor that misses its set rate: it turns F Hz faster (or, negative,
                         slower) than set (-5..5); G1's CT reports the rate it really turns at.
  --scan-wobble-hz F     a motor that wanders: up to F Hz about its rate, over 2 s (0..5).
  --block-sector A:B     something in front of the window: directions from A to B degrees
                         (clockwise, may cross 0, e.g. 40:75 or 350:10) give no return.
  --unplug-after-ms N    disconnect after N ms: the pseudo-terminal and LINK disappear (TCP: the
                         host is dropped and the port closed); the device loses power.
  --replug-after-ms N    come back N ms after the unplug with a new pseudo-terminal (LINK is
                         re-pointed), the device in its power-on state.

examples:
  ydscope-cli sim --model G6 --pty /tmp/lidar &       then: ydscope-cli info --port /tmp/lidar
  ydscope-cli sim --model G1 --scene room --tcp 127.0.0.1:2000 --lose-packets 0.01 --verbose
  ydscope-cli sim --model TG30 --pty /tmp/ydlidar --host-compat ydlidar-sdk --firmware 1.1
)";

// "MAJOR.MINOR" with the model's limits (G1's CT holds major 0..3, minor 0..31).
std::pair<std::uint8_t, std::uint8_t> parse_firmware(const std::string& text, const ModelProfile& profile) {
  const unsigned max_major = profile.model == Model::G1 ? 3 : 255;
  const unsigned max_minor = profile.model == Model::G1 ? 31 : 255;
  unsigned major = 0;
  unsigned minor = 0;
  const auto dot = text.find('.');
  const auto parse = [](std::string_view part, unsigned& value) {
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
  };
  if (dot == std::string::npos || !parse(std::string_view(text).substr(0, dot), major) ||
      !parse(std::string_view(text).substr(dot + 1), minor) || major > max_major || minor > max_minor)
    throw UsageError("--firmware needs MAJOR.MINOR with major 0.." + std::to_string(max_major) + " and minor 0.." +
                     std::to_string(max_minor) + " on the " + std::string(profile.name) + ", such as 1.2, not '" +
                     text + "'");
  return {static_cast<std::uint8_t>(major), static_cast<std::uint8_t>(minor)};
}

std::pair<std::string, std::uint16_t> parse_host_port(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0)
    throw UsageError("--tcp needs HOST:PORT, such as 127.0.0.1:2000, not '" + text + "'");
  const std::string port_text = text.substr(colon + 1);
  unsigned port = 0;
  const auto [ptr, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || ptr != port_text.data() + port_text.size() || port > 65535)
    throw UsageError("--tcp port must be a number from 0 to 65535, not '" + port_text + "'");
  return {text.substr(0, colon), static_cast<std::uint16_t>(port)};
}

int run_sim(std::span<const std::string> raw) {
  const Arguments args(raw,
                       {"model",
                        "pty",
                        "tcp",
                        "scene",
                        "pose",
                        "seed",
                        "serial",
                        "distance-scale",
                        "conventions",
                        "zero-log",
                        "corrupt",
                        "drop",
                        "lose-packets",
                        "stall-ms",
                        "stall-every-ms",
                        "health-bits",
                        "junk",
                        "unplug-after-ms",
                        "replug-after-ms",
                        "host-compat",
                        "firmware",
                        "delivery",
                        "scan-offset-hz",
                        "scan-wobble-hz",
                        "block-sector"},
                       {"verbose", "health-quirk"});

  const std::string model_name = args.required("model");
  const ModelProfile* profile = find_profile(model_name);
  if (!profile) throw UsageError("unknown model '" + model_name + "'; the models are " + std::string(model_names()));
  if (args.has("pty") == args.has("tcp")) throw UsageError("give exactly one of --pty LINK or --tcp HOST:PORT");

  SimServerOptions options;
  options.device.model = profile->model;
  options.device.scene = args.value("scene").value_or("demo");
  if (!make_scene(options.device.scene, 0))
    throw UsageError("unknown scene '" + options.device.scene + "'; the scenes are " + std::string(scene_names()));
  if (const auto pose = args.value("pose")) {
    std::string error;
    options.device.pose = parse_pose(*pose, error);
    if (!options.device.pose) throw UsageError("--pose: " + error);
    if (!make_scene(options.device.scene, 0)->sample_from(0, 0, 0, 0))
      throw UsageError("--pose needs a scene of walls to stand in: room or booth, not " + options.device.scene);
  }
  options.device.seed = static_cast<std::uint64_t>(args.integer("seed", 0, INT64_MAX).value_or(1));
  if (const auto serial = args.value("serial")) {
    options.device.serial = *serial;
    for (char& c : options.device.serial) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (!valid_sim_serial(options.device.serial))
      throw UsageError("--serial needs 16 characters 0-9 or A-F, such as 0471655879731342, not '" + *serial + "'");
  }
  options.device.distance_scale = args.number("distance-scale", 0.001, 1000.0);
  options.device.reading = reading_option(args).value_or(Reading::Field);
  options.device.health_quirk = args.has("health-quirk");
  if (const auto compat = args.value("host-compat")) {
    const auto parsed = host_compat_from_name(*compat);
    if (!parsed)
      throw UsageError("unknown --host-compat '" + *compat + "'; the choices are " + std::string(host_compat_names()));
    options.device.host_compat = *parsed;
  }
  if (const auto firmware = args.value("firmware"))
    std::tie(options.device.firmware_major, options.device.firmware_minor) = parse_firmware(*firmware, *profile);
  if (const auto delivery = args.value("delivery")) {
    std::string error;
    const auto parsed = parse_delivery(*delivery, &error);
    if (!parsed) throw UsageError("--delivery " + *delivery + ": " + error);
    options.delivery = *parsed;
  }
  FaultConfig& faults = options.device.faults;
  faults.corrupt_byte_rate = args.number("corrupt", 0.0, 1.0).value_or(0.0);
  faults.drop_byte_rate = args.number("drop", 0.0, 1.0).value_or(0.0);
  faults.lost_packet_rate = args.number("lose-packets", 0.0, 1.0).value_or(0.0);
  faults.stall_ms = args.integer("stall-ms", 0, 3'600'000).value_or(0);
  faults.stall_every_ms = args.integer("stall-every-ms", 0, 86'400'000).value_or(0);
  if ((faults.stall_ms > 0) != (faults.stall_every_ms > 0))
    throw UsageError("--stall-ms and --stall-every-ms go together: give both or neither");
  if (faults.stall_ms > 0 && faults.stall_ms >= faults.stall_every_ms)  // a stall that never ends
    throw UsageError("--stall-ms (" + std::to_string(faults.stall_ms) + ") must be shorter than --stall-every-ms (" +
                     std::to_string(faults.stall_every_ms) + "), or the virtual lidar never sends again");
  faults.health_bits = static_cast<std::uint8_t>(args.integer("health-bits", 0, 255).value_or(0));
  faults.junk_before_reply = static_cast<std::uint32_t>(args.integer("junk", 0, 4096).value_or(0));
  faults.scan_hz_offset = args.number("scan-offset-hz", -5.0, 5.0).value_or(0.0);
  faults.scan_hz_wobble = args.number("scan-wobble-hz", 0.0, 5.0).value_or(0.0);
  if (const auto block = args.value("block-sector")) {
    std::string error;
    const auto sector = parse_sector(*block, error);
    if (!sector) throw UsageError("--block-sector: " + error);
    faults.blocked_from_deg = sector->from_deg;
    faults.blocked_width_deg = sector->width_deg();
  }
  options.unplug_after = std::chrono::milliseconds(args.integer("unplug-after-ms", 0, 86'400'000).value_or(0));
  options.replug_after = std::chrono::milliseconds(args.integer("replug-after-ms", 0, 86'400'000).value_or(0));
  if (options.replug_after.count() > 0 && options.unplug_after.count() == 0)
    throw UsageError("--replug-after-ms needs --unplug-after-ms");
  options.zero_packet_log = args.value("zero-log").value_or("");

  if (args.has("pty")) {
    options.transport = SimTransport::Pty;
    options.pty_link = args.required("pty");
    if (options.pty_link.empty()) throw UsageError("--pty needs a path for the link, such as /tmp/lidar");
  } else {
    options.transport = SimTransport::Tcp;
    std::tie(options.tcp_host, options.tcp_port) = parse_host_port(args.required("tcp"));
  }
  if (args.has("verbose")) options.on_log = [](std::string_view line) { std::cerr << line << std::endl; };

  // Block the stop signals before the server thread starts, so it inherits the mask and this thread
  // alone takes them with sigwait: no handler, no race with the serving thread.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  SimServer server(options);
  server.start();
  std::cout << "ready " << server.device_path() << std::endl;
  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  if (args.has("verbose")) std::cerr << "stopping on signal " << signal_number << std::endl;
  server.stop();
  return kExitOk;
}

const RegisterCliCommand sim_command{
    {"sim", "serve a virtual lidar on a pseudo-terminal or TCP port", kSimHelp, &run_sim}};

}  // namespace
}  // namespace ydscope::cli
