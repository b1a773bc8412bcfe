#include "core/record/source_decoders.h"

namespace ydscope {

SourceDecoders::SourceDecoders(const std::vector<SourcePlan>& sources) {
  for (const SourcePlan& source : sources)
    decoders_.push_back(source.profile && source.conventions
                            ? std::make_unique<ScanDecoder>(*source.profile, *source.conventions, source.distance_scale)
                            : nullptr);
}

void SourceDecoders::feed(const RecordView& record, SourceLapCallback on_lap) {
  if (record.type == RecordType::DeviceToHost) feed(record.source, record.payload, record.t_ns, on_lap);
}

void SourceDecoders::feed(std::size_t source, std::span<const std::uint8_t> bytes, std::int64_t t_ns,
                          SourceLapCallback on_lap) {
  // A source the plan did not list, or whose model is unknown, has nothing to decode with.
  if (source >= decoders_.size() || !decoders_[source]) return;
  decoders_[source]->feed(bytes, t_ns, [&](const Lap& lap) { on_lap(source, lap); });
}

void SourceDecoders::finish(SourceLapCallback on_lap) {
  for (std::size_t source = 0; source < decoders_.size(); ++source)
    if (decoders_[source]) decoders_[source]->finish([&](const Lap& lap) { on_lap(source, lap); });
}

}  // namespace ydscope
