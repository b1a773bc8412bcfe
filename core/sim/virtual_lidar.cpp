#include "core/sim/virtual_lidar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/protocol/scan_packet.h"
#include "core/sim/line_pacer.h"
#include "core/sim/scan_stream.h"
#include "core/sim/posed_scene.h"
#include "core/sim/scene.h"

namespace ydscope {

namespace {

std::string hz_text(std::uint32_t centihz) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f Hz", centihz / 100.0);
  return text;
}

}  // namespace

VirtualLidar::VirtualLidar(const VirtualLidarConfig& config, std::int64_t now_ns)
    : profile_(&profile_for(config.model)),
      config_(config),
      conventions_(&conventions_for(*profile_, firmware_as_sdk_reads(config.firmware_major, config.firmware_minor),
                                    config.reading)),
      distance_scale_(config.distance_scale.value_or(conventions_->distance_scale)),
      scene_(make_scene(config.scene, config.seed)),
      line_(config.faults, config.seed),
      now_ns_(now_ns) {
  if (!scene_)
    throw std::invalid_argument("unknown scene '" + config.scene + "'; the scenes are " + std::string(scene_names()));
  if (config.pose) scene_ = std::make_unique<PosedScene>(std::move(scene_), *config.pose);
  if (!(distance_scale_ > 0.0)) throw std::invalid_argument("the distance scale must be positive");
  stream_ = std::make_unique<ScanStream>(*profile_, *conventions_, distance_scale_, *scene_, now_ns,
                                         config.firmware_major, config.firmware_minor, config.seed);
  pacer_ = std::make_unique<LinePacer>(profile_->default_baud);
  info_.model_code = profile_->model_code;
  info_.firmware_major = config.firmware_major;
  info_.firmware_minor = config.firmware_minor;
  info_.hardware = config.hardware;
  FaultRandom serial_random((config.seed ^ 0x5E41A1) + config.unit);
  for (auto& digit : info_.serial) digit = static_cast<std::uint8_t>(serial_random.below(10));
  if (!config.serial.empty()) {
    if (!valid_sim_serial(config.serial))
      throw std::invalid_argument("a serial is 16 characters 0-9 or A-F, not '" + config.serial + "'");
    for (std::size_t i = 0; i < info_.serial.size(); ++i)  // one character per byte, as serial_string reads it
      info_.serial[i] = static_cast<std::uint8_t>(std::stoi(config.serial.substr(i, 1), nullptr, 16));
  }
  reset_to_power_on();
}

VirtualLidar::~VirtualLidar() = default;

FaultCounters VirtualLidar::fault_counters() const {
  FaultCounters counters = line_.counters();  // what the line did; the window's block is the stream's
  counters.blocked_samples = stream_->blocked_samples();
  return counters;
}

bool valid_sim_serial(std::string_view serial) {
  return serial.size() == DeviceInfo{}.serial.size() &&
         serial.find_first_not_of("0123456789ABCDEF") == std::string_view::npos;
}

void VirtualLidar::reset_to_power_on() {
  mode_ = DeviceMode::Idle;
  scan_centihz_ = static_cast<std::uint32_t>(std::lround(profile_->default_scan_hz * 100.0));
  ranging_index_ = profile_->ranging_index(profile_->default_ranging_khz).value_or(0);
  protection_ = false;
  low_power_ = true;
  direction_ = MotorDirection::Clockwise;
  constant_hz_ = true;
  saw_a5_ = false;
  line_.clear_stalls();
  pacer_->clear();
}

void VirtualLidar::log(std::int64_t t_ns, const std::string& line) const {
  if (log_) log_(t_ns, line);
}

void VirtualLidar::receive(std::span<const std::uint8_t> bytes, std::int64_t now_ns) {
  advance(now_ns);
  for (const std::uint8_t byte : bytes) {
    if (!saw_a5_) {
      if (byte == kCommandStart) {
        saw_a5_ = true;
      } else {
        ++counters_.stray_bytes;
      }
      continue;
    }
    saw_a5_ = false;
    if (byte == kCommandStart) {  // the earlier A5 had no code: it was stray, this one starts anew
      ++counters_.stray_bytes;
      saw_a5_ = true;
      continue;
    }
    handle_command(byte, now_ns_);
  }
}

void VirtualLidar::start_scan(std::int64_t now_ns) {
  mode_ = DeviceMode::Scanning;
  ++counters_.scans_started;
  last_keepalive_ns_ = now_ns;
  answer(Command::Scan, {}, now_ns);
  // Units with a module board announce it after the header; YDLidar-SDK waits 1 s for it.
  if (sends_device_info_after_scan_header(config_.host_compat))
    answer(Command::DeviceInfo, encode_device_info(info_), now_ns);
  stream_->set_health(faults().health_bits);
  stream_->set_motor_error(faults().scan_hz_offset, faults().scan_hz_wobble);
  stream_->set_blocked_sector(faults().blocked_from_deg, faults().blocked_width_deg);
  stream_->start(now_ns, scan_centihz_, ranging_khz());
  line_.arm_periodic_stalls(now_ns);
  log(now_ns, "scanning at " + hz_text(scan_centihz_) + ", " + std::to_string(ranging_khz()) + " kHz, " +
                  std::to_string(stream_->samples_per_lap()) + " points per lap");
}

void VirtualLidar::stop_scan(std::int64_t now_ns, std::string_view why) {
  mode_ = DeviceMode::Idle;
  line_.disarm_periodic_stalls();
  pacer_->drop_unstarted(now_ns);
  log(now_ns, "idle: " + std::string(why));
}

void VirtualLidar::advance(std::int64_t now_ns) {
  now_ns_ = std::max(now_ns_, now_ns);
  while (mode_ == DeviceMode::Scanning) {
    const std::int64_t ready = stream_->next_ready_ns();
    const std::int64_t deadline = protection_ ? last_keepalive_ns_ + kPowerDownTimeoutNs : kNever;
    if (const auto stall_from = line_.take_due_stall(std::min(ready, now_ns_))) {
      stall(*stall_from, faults().stall_ms * 1'000'000);
      continue;
    }
    if (deadline <= now_ns_ && deadline <= ready) {
      ++counters_.power_down_stops;
      stop_scan(deadline, "power-down protection: no A5 60 for 3 s");
      break;
    }
    if (ready > now_ns_) break;
    generate_packet();
  }
}

void VirtualLidar::generate_packet() {
  packet_.clear();
  TruthPacket truth;
  const StreamPacket sp =
      stream_->next(packet_, truth_ ? &truth.points : nullptr, truth_ ? &truth.scene_angle_deg : nullptr);
  ++counters_.packets;
  if (sp.index == 0) ++counters_.zero_packets;
  counters_.points += sp.lsn;

  const PacketFate fate = line_.apply(packet_, sp.packet_offset + kPacketHeaderSize, sp.index == 0, sp.ready_ns);
  truth.lost = fate.lost;
  truth.corrupted = fate.corrupted;
  truth.altered = fate.altered;
  if (!fate.lost) pacer_->enqueue(sp.ready_ns, packet_, sp.index == 0 ? packet_.size() : LinePacer::kNoZeroEnd, true);
  if (truth_) {
    truth.lap = sp.lap;
    truth.index = sp.index;
    truth.ct = sp.ct;
    truth.ready_ns = sp.ready_ns;
    truth_(truth);
  }
}

void VirtualLidar::produce(std::int64_t now_ns, std::vector<std::uint8_t>& out,
                           std::vector<std::size_t>* zero_packet_ends) {
  advance(now_ns);
  const std::size_t base = out.size();
  const std::size_t zero_base = zero_packet_ends ? zero_packet_ends->size() : 0;
  pacer_->drain(now_ns_, out, zero_packet_ends);
  line_.drop_bytes(out, base, zero_packet_ends, zero_base);
  counters_.bytes_out += out.size() - base;
  counters_.packets_sent = pacer_->packets_sent();
}

std::int64_t VirtualLidar::next_event_ns() const {
  std::int64_t next = pacer_->next_completion_ns();
  if (mode_ == DeviceMode::Scanning) {
    next = std::min(next, stream_->next_ready_ns());
    if (protection_) next = std::min(next, last_keepalive_ns_ + kPowerDownTimeoutNs);
    next = std::min(next, line_.next_periodic_stall_ns());
  }
  return next;
}

void VirtualLidar::power_cycle(std::int64_t now_ns) {
  now_ns_ = std::max(now_ns_, now_ns);
  reset_to_power_on();
  log(now_ns_, "power cycled: idle, power-on defaults");
}

void VirtualLidar::set_faults(const FaultConfig& faults) {
  line_.set_config(faults, mode_ == DeviceMode::Scanning ? std::optional(now_ns_) : std::nullopt);
  stream_->set_health(faults.health_bits);
  stream_->set_motor_error(faults.scan_hz_offset, faults.scan_hz_wobble);
  stream_->set_blocked_sector(faults.blocked_from_deg, faults.blocked_width_deg);
}

void VirtualLidar::stall(std::int64_t from_ns, std::int64_t duration_ns) {
  line_.stall(from_ns, duration_ns);
  log(from_ns, "stalling for " + std::to_string(duration_ns / 1'000'000) + " ms");
}

}  // namespace ydscope
