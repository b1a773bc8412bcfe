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

// The packet decoder's and the lap assembler's counters side by side, as one set. Bytes held in
// front of a zero packet that may be G1's LastCRC count as pending, not as resync (counters()).
struct DecoderCounters : PacketCounters, LapCounters {};

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
