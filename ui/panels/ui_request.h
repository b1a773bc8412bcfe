#pragma once
// What the user asks for through a panel, a key or the mouse, as typed values. Panels never act
// themselves: they append a request to UiModel::requests, and after the frame the app carries each
// out in order, sending device commands to the session behind the current source. One path for
// every intent (the device's, the replay's and the virtual lidar's), and no session in ui/.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "core/protocol/unit_conventions.h"
#include "core/sim/delivery.h"
#include "core/sim/faults.h"
#include "core/sim/host_compat.h"
#include "ui/view/scene/source_set.h"

namespace ydscope::ui {

// A source to start in place of the current one.
struct ConnectRequest {
  enum class Kind { Port, Sim, Replay } kind = Kind::Port;
  std::string address;                          // port path / tcp URL, or the recording for Replay
  std::optional<std::string> model;             // Port: fixed model (empty = detect); Sim: the model;
                                                // Replay: decode as this one (empty = the recording's)
  std::optional<std::uint32_t> baud;            // Port only
  std::string scene = "demo";                   // Sim only
  FaultConfig faults;                           // Sim only
  HostCompat host_compat = HostCompat::Manual;  // Sim only: what it answers beyond the manual
  std::uint8_t firmware_major = 1;              // Sim only: what its device info reports
  std::uint8_t firmware_minor = 2;
  DeliveryModel delivery;      // Sim only: how its bytes reach the host
  std::uint32_t sim_unit = 0;  // Sim only: the how-manyth virtual lidar of this window (its serial)
  double replay_speed = 1.0;   // Replay only: 1 as recorded, within the panel's slider
  bool replay_loop = true;     // Replay only: false stops at the end and says so
};

// ---- the source -------------------------------------------------------------------------------
struct Disconnect {};
struct RefreshPorts {};
struct ControlReplay {
  bool paused = false;
  double speed = 1.0;
  bool loop = true;
};
struct SetSimFaults {
  FaultConfig faults;
};
struct UnplugSim {};
struct ReplugSim {};

// ---- the device (each outcome is shown beside the control that asked) -------------------------
struct SetScanHz {
  double hz = 0;
};
struct SetRangingKhz {
  std::uint16_t khz = 0;
};
struct RefreshHealth {};
// The acceptance check of `ydscope-cli check` on this lidar (docs/check.md), its report opened.
struct RunCheck {};
// Either file, or both at once: every byte as .ydrec (the session writes it), and the live topics
// as MCAP (written beside the I/O thread).
struct StartRecording {
  std::string path;       // .ydrec; empty: none
  std::string mcap_path;  // .mcap; empty: none
};
struct StopRecording {};  // whichever run
struct SetDistanceScale {
  std::optional<double> mm_per_count;  // empty: back to the conventions' own
};
struct SetReading {
  Reading reading = Reading::Field;  // read the unit as real units write, or as its manual says
};

// ---- out to Foxglove ----------------------------------------------------------------------------
// Serve the current source over the Foxglove WebSocket protocol, or stop serving it.
struct SetShare {
  bool on = false;
};

// ---- the source list (several lidars at once) ---------------------------------------------------
// The panels show, and command, this source from the next frame.
struct SelectSource {
  std::size_t index = 0;
};
// Name, colour, pose, hidden and paused of a source, as edited in the Sources panel or by mouse.
struct SetSourceLook {
  std::size_t index = 0;
  SourceLook look;
};
// Another source at the end of the list; `name` may be empty (then the model or "lidar").
struct AddSource {
  ConnectRequest request;
  std::string name;
};
struct RemoveSource {
  std::size_t index = 0;
};
// Match every lidar against the first from the walls they share (ui/view/scene/source_alignment.h);
// the answer waits in the Sources tab until AnswerAlignment.
struct AlignSources {};
struct AnswerAlignment {
  bool apply = false;  // set the poses found; false: leave every pose as it is
};

// ---- the view and files -----------------------------------------------------------------------
struct ResetView {};
struct SaveScreenshot {};
struct ExportLapCsv {
  bool every_shown_lap = false;  // else the newest lap on screen
};
struct ExportLapMcap {};  // every shown lap, as /scan and /points
struct WatchSector {
  std::string spec;  // "260:280 [1500:2500]"
};
struct UnwatchSector {
  std::size_t index = 0;
};

using UiRequest =
    std::variant<ConnectRequest, Disconnect, RefreshPorts, ControlReplay, SetSimFaults, UnplugSim, ReplugSim, SetScanHz,
                 SetRangingKhz, RefreshHealth, RunCheck, StartRecording, StopRecording, SetDistanceScale, SetReading,
                 SetShare, ResetView, SaveScreenshot, ExportLapCsv, ExportLapMcap, WatchSector, UnwatchSector,
                 SelectSource, SetSourceLook, AddSource, RemoveSource, AlignSources, AnswerAlignment>;

// The requests that change the source list rather than one source.
template <class R>
inline constexpr bool is_source_list_request =
    std::is_same_v<R, SelectSource> || std::is_same_v<R, SetSourceLook> || std::is_same_v<R, AddSource> ||
    std::is_same_v<R, RemoveSource> || std::is_same_v<R, AlignSources> || std::is_same_v<R, AnswerAlignment>;
// The requests one source carries out alone: its device's commands, its replay, its virtual lidar.
template <class R>
inline constexpr bool is_device_request =
    std::is_same_v<R, ControlReplay> || std::is_same_v<R, SetSimFaults> || std::is_same_v<R, UnplugSim> ||
    std::is_same_v<R, ReplugSim> || std::is_same_v<R, SetScanHz> || std::is_same_v<R, SetRangingKhz> ||
    std::is_same_v<R, RefreshHealth> || std::is_same_v<R, RunCheck> || std::is_same_v<R, SetDistanceScale> ||
    std::is_same_v<R, SetReading>;

}  // namespace ydscope::ui
