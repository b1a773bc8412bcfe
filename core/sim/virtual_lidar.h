#pragma once
// VirtualLidar: a G1, G6 or TG15/30/50 as its manual describes it, as a pure deterministic model.
// No threads and no clock inside: the caller passes the time (any monotonic ns clock) with every
// call. Host bytes go in through receive(); device bytes come out of produce(), paced to real time
// and to the line rate of the model's baud (10 bits per byte). SimServer puts it behind a port.
//
// Behaviour (see each manual):
// - Power-on: idle. A5 60 -> continuous reply header A5 5A 05 00 00 40 81, then scan packets.
//   A5 65 stops without a reply (packets not yet begun on the line are dropped, as a UART FIFO).
// - While scanning every command except A5 65 is ignored and counted (the manuals forbid them).
//   Exception, power-down protection on: A5 60 is the keep-alive the manuals ask for; it restarts
//   the 3 s watchdog and answers nothing (the manuals' note: only the first A5 60 from the stopped
//   state gets the full reply header). Without a keep-alive for 3 s the scan stops by itself.
// - A5 D9 toggles protection; the reply is 00 when it is now on, 01 when now off (the manuals).
// - Commands the model's manual does not list get no reply at all (counted as unsupported), unless
//   a host compatibility mode (VirtualLidarConfig::host_compat, core/sim/host_compat.h) answers them.
// - Restart (G1 A5 40, G6/TG A5 80): no reply; back to the power-on state (idle, defaults).
// - Stream: laps of N = round(ranging Hz / scan Hz) samples evenly spaced over 360 degrees; the
//   zero packet (LSN 1) holds sample 0, then packets of up to 40 samples. With the motor faults
//   (FaultConfig::scan_hz_offset, scan_hz_wobble) each lap runs at the motor's actual rate, and N
//   follows it. Each sample's range is taken from the scene at the direction the host's
//   second-level correction will give it (within 0.01 degree); at an edge where no direction is consistent the sample reports no return.
//   G1: CT by packet index (0 scan Hz, 1 version, 3 health, else a debug value) and the LastCRC
//   byte (CRC8 of the previous lap's CT bytes, 0 before the first zero packet) in front of every
//   zero packet; samples carry the scene's interference flags.
// - Settings not reflected in the stream (documented here so nobody looks for them): motor
//   direction, constant frequency and low power are state with correct replies only.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/frame/pose.h"
#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/reply.h"
#include "core/protocol/unit_conventions.h"
#include "core/sim/faults.h"
#include "core/sim/host_compat.h"
#include "core/sim/line_faults.h"

namespace ydscope {

class Scene;
class LinePacer;
class ScanStream;

enum class DeviceMode : std::uint8_t { Idle, Scanning };

struct VirtualLidarConfig {
  Model model = Model::G6;
  std::string scene = "demo";  // "room", "demo" or "booth" (scene_names())
  std::uint64_t seed = 1;      // scene noise, moving objects, serial number, fault decisions
  // The serial A5 90 reports, 16 characters 0-9 and A-F (valid_sim_serial); empty: made from
  // the seed. Two units told apart by serial (core/frame/unit_identity.h) are two of these.
  std::string serial;
  // Which of several virtual lidars sharing one seed (as the app starts them): each unit makes a
  // serial of its own from the seed, the rest of its bytes unchanged. Unit 0 is the seed's serial.
  std::uint32_t unit = 0;
  // Where it stands in the scene (core/sim/posed_scene.h); empty: at the scene's origin.
  std::optional<Pose> pose;
  FaultConfig faults;
  // Field: what a real unit of this model and firmware emits (rates, scale, TG's byte before the
  // zero packet); Manual: the manual's literal reading (unit_conventions.h).
  Reading reading = Reading::Field;
  // Encode ranges with yet another scale (emulates other firmware variants).
  std::optional<double> distance_scale;
  // Some units answer only the other health command (A5 91 <-> A5 92); this emulates them.
  bool health_quirk = false;
  // Device-info firmware in the manuals' byte order (low byte major); also G1's CT version (major
  // 0..3, minor 0..31). YDLidar-SDK reads the two bytes the other way round (see host_compat.h).
  std::uint8_t firmware_major = 1;
  std::uint8_t firmware_minor = 2;
  std::uint8_t hardware = 1;
  // Manual: only the manual's answers. YdlidarSdk: also what the vendor SDK asks beyond them.
  HostCompat host_compat = HostCompat::Manual;
};

// Whether `serial` is what VirtualLidarConfig::serial takes: 16 characters 0-9 or A-F (upper case).
bool valid_sim_serial(std::string_view serial);

struct DeviceCounters {
  std::uint64_t commands = 0;             // A5 xx pairs received (any code)
  std::uint64_t replies = 0;              // reply headers queued (single and continuous)
  std::uint64_t ignored_during_scan = 0;  // commands other than A5 65 (and keep-alive A5 60) while scanning
  std::uint64_t unsupported = 0;          // codes the model's manual does not list: no reply
  std::uint64_t stray_bytes = 0;          // host bytes that were not part of an A5 xx pair
  std::uint64_t keepalives = 0;           // A5 60 during a scan with power-down protection on
  std::uint64_t scans_started = 0;
  std::uint64_t power_down_stops = 0;  // scans stopped by the 3 s watchdog
  std::uint64_t restarts = 0;
  std::uint64_t packets = 0;  // scan packets generated (including those faults kept off the line)
  std::uint64_t zero_packets = 0;
  std::uint64_t packets_sent = 0;  // scan packets whose last byte has gone out on the line
  std::uint64_t points = 0;
  std::uint64_t bytes_out = 0;  // bytes handed out by produce()
};

// Ground truth of one generated packet, for tests: what a correct host decodes from it.
struct TruthPacket {
  std::uint64_t lap = 0;    // 0 = the lap begun by the first zero packet of this scan
  std::uint32_t index = 0;  // index within the lap; 0 = zero packet
  std::uint8_t ct = 0;
  bool lost = false;       // never sent (lost-packet fault or stall)
  bool corrupted = false;  // sent with a broken checksum
  // Sent with bytes flipped that cancel in its checksum (the XOR of 16-bit words): the host takes
  // it as good, but its points are not `points`. Rare: two flips of the same bit in the same lane.
  bool altered = false;
  std::int64_t ready_ns = 0;     // when its last sample was measured
  std::vector<LapPoint> points;  // corrected angle in [0, 360), range in mm, flag
  // Direction the scene was sampled at for each point; equals the point's angle once the
  // fixed-point iteration converged (it may not at an object's edge).
  std::vector<float> scene_angle_deg;
};

class VirtualLidar {
 public:
  using LogFn = std::function<void(std::int64_t t_ns, std::string_view line)>;
  using TruthFn = std::function<void(const TruthPacket&)>;
  static constexpr std::int64_t kNever = LineFaults::kNever;
  static constexpr std::int64_t kPowerDownTimeoutNs = 3'000'000'000;

  // Throws std::invalid_argument for an unknown scene name.
  explicit VirtualLidar(const VirtualLidarConfig& config, std::int64_t now_ns = 0);
  ~VirtualLidar();
  VirtualLidar(const VirtualLidar&) = delete;
  VirtualLidar& operator=(const VirtualLidar&) = delete;

  // Bytes from the host, received at now_ns (non-decreasing across all calls).
  void receive(std::span<const std::uint8_t> bytes, std::int64_t now_ns);
  // Appends every byte whose transmission completed by now_ns. zero_packet_ends, when given, gets
  // the offset in `out` just past each zero packet's last byte (for latency measurements).
  void produce(std::int64_t now_ns, std::vector<std::uint8_t>& out,
               std::vector<std::size_t>* zero_packet_ends = nullptr);
  // When produce() will next have bytes, or the watchdog fires; kNever when nothing is pending.
  std::int64_t next_event_ns() const;

  // Power lost and back (unplug/replug): power-on state, queued bytes gone. Counters are kept.
  void power_cycle(std::int64_t now_ns);
  void set_faults(const FaultConfig& faults);
  const FaultConfig& faults() const { return line_.config(); }
  HostCompat host_compat() const { return config_.host_compat; }
  // Sends nothing from from_ns for duration_ns (packets and replies due then are discarded).
  void stall(std::int64_t from_ns, std::int64_t duration_ns);

  const ModelProfile& profile() const { return *profile_; }
  DeviceMode mode() const { return mode_; }
  std::uint32_t scan_centihz() const { return scan_centihz_; }
  std::uint8_t ranging_index() const { return ranging_index_; }
  std::uint16_t ranging_khz() const { return profile_->ranging_khz[ranging_index_]; }
  bool power_down_protection() const { return protection_; }
  bool low_power() const { return low_power_; }
  MotorDirection motor_direction() const { return direction_; }
  bool constant_frequency() const { return constant_hz_; }
  DeviceInfo device_info() const { return info_; }
  double distance_scale() const { return distance_scale_; }
  const UnitConventions& conventions() const { return *conventions_; }
  const Scene& scene() const { return *scene_; }
  const DeviceCounters& counters() const { return counters_; }
  FaultCounters fault_counters() const;

  // Human-readable events (commands received, mode changes) for --verbose.
  void set_log(LogFn log) { log_ = std::move(log); }
  // Called for every generated packet with what the host should decode from it.
  void set_truth(TruthFn truth) { truth_ = std::move(truth); }

 private:
  void reset_to_power_on();
  void advance(std::int64_t now_ns);
  void generate_packet();
  void handle_command(std::uint8_t code, std::int64_t now_ns);
  void answer(Command command, std::span<const std::uint8_t> payload, std::int64_t now_ns);
  void answer_compat(const CompatCommand& extra, std::int64_t now_ns);
  void send_reply(std::span<const std::uint8_t> reply, std::int64_t now_ns);
  HealthReply health_reply() const;
  void start_scan(std::int64_t now_ns);
  void stop_scan(std::int64_t now_ns, std::string_view why);
  void log(std::int64_t t_ns, const std::string& line) const;

  const ModelProfile* profile_;
  VirtualLidarConfig config_;
  const UnitConventions* conventions_;
  double distance_scale_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<ScanStream> stream_;
  std::unique_ptr<LinePacer> pacer_;
  LineFaults line_;  // what of the packets and replies reaches the line
  DeviceInfo info_;

  DeviceMode mode_ = DeviceMode::Idle;
  std::uint32_t scan_centihz_ = 0;
  std::uint8_t ranging_index_ = 0;
  bool protection_ = false;
  bool low_power_ = true;
  MotorDirection direction_ = MotorDirection::Clockwise;
  bool constant_hz_ = true;
  std::int64_t now_ns_ = 0;
  std::int64_t last_keepalive_ns_ = 0;
  bool saw_a5_ = false;

  DeviceCounters counters_;
  LogFn log_;
  TruthFn truth_;
  std::vector<std::uint8_t> packet_;       // scratch for one packet
  std::vector<std::uint8_t> reply_bytes_;  // scratch for one reply
};

}  // namespace ydscope
