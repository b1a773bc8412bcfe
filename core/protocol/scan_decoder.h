#pragma once
// ScanDecoder: bytes of an A5 60 stream in, complete laps out. PacketDecoder + LapAssembler for
// one model, with one set of counters. This is what the session, the CLI and the tests use.
#include <cstdint>
#include <optional>
#include <span>

#include "core/protocol/function_ref.h"
#include "core/protocol/lap.h"
#include "core/protocol/lap_assembler.h"
#include "core/protocol/lap_end_forecast.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/packet_decoder.h"
#include "core/protocol/unit_conventions.h"

namespace ydscope {

struct DecoderCounters {
  std::uint64_t bytes = 0;              // every byte fed
  std::uint64_t packets = 0;            // scan packets with a valid checksum
  std::uint64_t zero_packets = 0;       // of which CT bit 0 was set
  std::uint64_t checksum_errors = 0;    // packets dropped for a bad checksum
  std::uint64_t resync_bytes = 0;       // bytes skipped hunting a header (junk, reply headers, failed starts)
  std::uint64_t pending_bytes = 0;      // bytes of a packet not complete yet (cut off at end of stream)
  std::uint64_t laps = 0;               // complete laps published
  std::uint64_t discarded_packets = 0;  // packets outside a lap: before the first zero packet, after a cut
  std::uint64_t cut_laps = 0;           // laps closed without their zero packet (Lap::end)
  std::uint64_t crc_ok = 0;             // G1 laps whose CT CRC8 matched
  std::uint64_t crc_mismatches = 0;     // G1 laps whose CT CRC8 did not match
  std::uint64_t crc_unknown = 0;        // G1 laps closed without a LastCRC byte
  std::uint64_t overflow_points = 0;    // points dropped from laps longer than Lap::kMaxPoints
};

using LapCallback = FunctionRef<void(const Lap&)>;

class ScanDecoder {
 public:
  // Reads the unit as `conventions` say; distance_scale overrides their scale (mm per raw unit
  // after the flag bits).
  ScanDecoder(const ModelProfile& profile, const UnitConventions& conventions,
              std::optional<double> distance_scale = std::nullopt);
  // The manual's reading, as the tests that hold the decoder to the manuals want.
  explicit ScanDecoder(const ModelProfile& profile, std::optional<double> distance_scale = std::nullopt);

  // Consumes all of `bytes` received at rx_ns; calls on_lap for every lap completed. The Lap is
  // valid only during the call (copy it, e.g. into a LapStream).
  void feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns, LapCallback on_lap);

  // End of stream (file decoding): lets packets hidden behind an incomplete false start out.
  void finish(LapCallback on_lap);

  // How many bytes can arrive before the next lap could close: how long a reader may leave input
  // waiting without delaying a lap (see LapEndForecast).
  LapEndOutlook lap_end_outlook() const { return forecast_.outlook(packets_.partial_packet()); }

  DecoderCounters counters() const;
  const ModelProfile& profile() const { return *profile_; }
  const UnitConventions& conventions() const { return *conventions_; }
  double distance_scale() const { return assembler_.distance_scale(); }
  // Back to a fresh decoder (buffers, lap state and counters).
  void reset();

 private:
  const ModelProfile* profile_;
  const UnitConventions* conventions_;
  PacketDecoder packets_;
  LapAssembler assembler_;
  LapEndForecast forecast_;
};

}  // namespace ydscope
