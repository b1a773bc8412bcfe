#pragma once
// One full revolution of the lidar: from a zero packet (inclusive) to the next (exclusive).
// Laps live preallocated in each consumer's LapRing (core/stream), so the point storage keeps its capacity between uses.
#include <cstdint>
#include <optional>
#include <vector>

namespace ydscope {

// G1 interference flag (S & 3): 2 specular reflection, 3 ambient light. Always 0 on G6/TG.
enum class PointFlag : std::uint8_t { None = 0, Reserved = 1, Specular = 2, AmbientLight = 3 };

struct LapPoint {
  float angle_deg;  // corrected, in [0, 360)
  float range_mm;   // 0 means no return
  PointFlag flag;
};

// Verdict of G1's CRC8 over the lap's CT bytes, compared with the LastCRC byte that closes it.
// Unknown: no byte lay between the lap's last packet and the closing zero packet, so there was
// nothing to compare with (the CT information is kept, but unverified).
enum class CrcVerdict : std::uint8_t { NotApplicable, Ok, Mismatch, Unknown };

// How a lap ended. Only a zero packet ends one rotation; the other two are cut short so that no
// lap ever holds more than one turn (a real X4 capture's start-up lap held two, 54 packets over
// 720 degrees), and the packets after the cut are dropped until the next zero packet.
enum class LapEnd : std::uint8_t {
  ZeroPacket,        // the next lap's zero packet arrived
  MissedZeroPacket,  // the angle came round past the lap's start again: its closing zero packet was lost
  Stall,             // the stream went quiet and came back elsewhere in the turn
};

// Longer than any wait between two reads of a flowing stream (the read hold is at most 80 ms,
// plus timer lateness), shorter than any outage worth telling about: a wait longer than this
// inside a lap is a stall, and the lap's duration says nothing about the motor.
inline constexpr std::int64_t kStreamStallNs = 250'000'000;

struct FirmwareVersion {
  std::uint8_t major = 0;
  std::uint8_t minor = 0;
};

struct Lap {
  // Enough for the slowest scan at the fastest ranging rate (18 kHz at 1 Hz) with headroom; a
  // lap longer than that (a stream whose zero packets were lost) is cut and says how much.
  static constexpr std::size_t kMaxPoints = 24000;

  std::uint64_t index = 0;       // 0 for the first complete lap of a stream
  std::vector<LapPoint> points;  // in received order
  // G1 CT information; empty on other models or when the packet carrying it was not seen.
  std::optional<double> scan_hz;
  std::optional<std::uint8_t> health_bits;
  std::optional<FirmwareVersion> version;
  CrcVerdict crc = CrcVerdict::NotApplicable;
  std::uint32_t packets = 0;          // valid scan packets in this lap
  std::uint32_t checksum_errors = 0;  // packets of this lap dropped for a bad checksum
  std::uint32_t cut_points = 0;       // samples beyond kMaxPoints, dropped (only a damaged stream)
  std::int64_t first_rx_ns = 0;       // steady-clock receive time of the lap's first byte
  std::int64_t last_rx_ns = 0;        // receive time of the byte that closed the lap
  // The triangulation correction was added to the angles (not on a time-of-flight TG read as the
  // field reads it): analysis that needs the first-level angles takes it off only then.
  bool angles_corrected = true;
  LapEnd end = LapEnd::ZeroPacket;
  std::int64_t longest_wait_ns = 0;  // longest receive-time wait between two packets of the lap

  Lap() { points.reserve(kMaxPoints); }
  // CT information is trusted only when the CRC8 did not fail.
  bool ct_info_trusted() const { return crc != CrcVerdict::Mismatch; }
  // One turn heard without a stall: only then does the lap's duration time the motor.
  bool whole() const { return end == LapEnd::ZeroPacket && longest_wait_ns <= kStreamStallNs; }
};

}  // namespace ydscope
