#include "core/protocol/scan_decoder.h"

namespace ydscope {

namespace {

// Routes the framer's events into the assembler (and the forecast) and hands completed laps to
// the caller.
class AssemblingSink final : public PacketSink {
 public:
  AssemblingSink(LapAssembler& assembler, LapEndForecast& forecast, LapCallback on_lap)
      : assembler_(assembler), forecast_(forecast), on_lap_(on_lap) {}
  void on_packet(const PacketView& packet) override {
    forecast_.observe(packet);
    if (assembler_.add_packet(packet)) on_lap_(assembler_.lap());
  }
  void on_checksum_error() override { assembler_.add_checksum_error(); }

 private:
  LapAssembler& assembler_;
  LapEndForecast& forecast_;
  LapCallback on_lap_;
};

}  // namespace

ScanDecoder::ScanDecoder(const ModelProfile& profile, const UnitConventions& conventions,
                         std::optional<double> distance_scale)
    : profile_(&profile),
      conventions_(&conventions),
      packets_(conventions.byte_before_zero != ByteBeforeZero::None),
      assembler_(profile, conventions, distance_scale.value_or(conventions.distance_scale)) {}

ScanDecoder::ScanDecoder(const ModelProfile& profile, std::optional<double> distance_scale)
    : ScanDecoder(profile, conventions_for(profile, std::nullopt, Reading::Manual), distance_scale) {}

void ScanDecoder::feed(std::span<const std::uint8_t> bytes, std::int64_t rx_ns, LapCallback on_lap) {
  AssemblingSink sink(assembler_, forecast_, on_lap);
  packets_.feed(bytes, rx_ns, sink);
}

void ScanDecoder::finish(LapCallback on_lap) {
  AssemblingSink sink(assembler_, forecast_, on_lap);
  packets_.finish(sink);
}

DecoderCounters ScanDecoder::counters() const {
  const PacketCounters& p = packets_.counters();
  const LapCounters& l = assembler_.counters();
  DecoderCounters c{p, l};
  // Until the next packet says whether it was G1's LastCRC, that byte is pending, not a resync:
  // the session publishes these counters after every read, and a read can end right after it.
  if (packets_.may_hold_last_crc()) {
    --c.resync_bytes;
    ++c.pending_bytes;
  }
  return c;
}

void ScanDecoder::reset() {
  packets_.reset();
  assembler_.reset();
  forecast_.reset();
}

}  // namespace ydscope
