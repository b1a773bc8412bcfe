#pragma once
// What a session tells the rest of the program: the device's details, its health, the outcome of a
// command, and the snapshot of the whole link. Plain values with no Boost (the build checks), so the
// UI and the analysis code read them without the I/O machinery behind session.h.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/snapshot/counter_snapshot.h"
#include "core/snapshot/link_state.h"
#include "core/protocol/commands.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/unit_conventions.h"
#include "core/stream/lap_stream.h"

namespace ydscope {

struct DeviceDetails {
  const ModelProfile* profile = nullptr;  // the model in use (detected or configured)
  std::uint8_t model_code = 0;            // as the device reported it
  FirmwareVersion firmware;
  std::uint8_t hardware = 0;
  std::string serial;  // 16 serial bytes rendered as text
};

struct HealthReport {
  Command command = Command::HealthStatusCode;  // the command that answered (A5 91 or A5 92)
  std::uint8_t status = 0;                      // G1: module bits; G6/TG: 0 ok, 1 warning, 2 error
  std::uint16_t error_code = 0;
  std::string summary;  // "ok", "error (code 0x0012)", "sensor, encoder abnormal"
};

// The outcome of one intent, also kept as SessionSnapshot::last_result.
struct CommandResult {
  bool ok = false;
  std::string what;     // "set scan frequency to 10.0 Hz"
  std::string message;  // read-back on success, one actionable sentence on failure
  std::optional<double> scan_hz;
  std::optional<std::uint16_t> ranging_khz;
  std::optional<bool> power_down_protection;
  std::optional<HealthReport> health;
};
using CommandCallback = std::function<void(const CommandResult&)>;

struct SessionSnapshot {
  LinkState state = LinkState::Idle;
  std::string message;  // what is happening or what went wrong, in words
  std::string link;     // the link's describe(): "/dev/ttyUSB0 at 512000 baud"
  std::uint32_t baud = 0;
  std::optional<DeviceDetails> device;
  std::optional<HealthReport> health;
  std::optional<double> scan_hz;                 // set value (A5 0D), not the measured rate
  std::optional<std::uint16_t> ranging_khz;      // A5 D1
  std::optional<bool> power_down_protection;     // as set or re-applied, else off (power-on)
  double distance_scale = 0;                     // mm per count in use
  const UnitConventions* conventions = nullptr;  // how the bytes are read (with the scale above)
  bool busy = false;                             // a command is running
  std::string busy_what;
  std::optional<CommandResult> last_result;
  bool recording = false;
  std::string recording_path;
  CounterSnapshot counters;
  std::uint64_t queue_dropped = 0;          // laps() ring: laps it could not take (its consumer was behind)
  std::uint64_t queue_skipped = 0;          // laps() ring: laps drained but passed over (drain_newest)
  std::vector<LapConsumerStats> consumers;  // every consumer of the lap stream, laps() first
};

}  // namespace ydscope
