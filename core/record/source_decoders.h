#pragma once
// One ScanDecoder per source of a recording, each with its source's model and distance scale
// (RecordingPlan::sources), so the bytes of several lidars recorded in one file never mix. A
// version-1 recording is one source, decoded as it always was.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "core/protocol/function_ref.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_plan.h"

namespace ydscope {

class SourceDecoders {
 public:
  using SourceLapCallback = FunctionRef<void(std::size_t source, const Lap&)>;

  // A source without a profile (its model unknown) is not decoded: its bytes are passed over.
  explicit SourceDecoders(const std::vector<SourcePlan>& sources);

  // The device bytes of `record` (other records are ignored) into its source's decoder.
  void feed(const RecordView& record, SourceLapCallback on_lap);
  void feed(std::size_t source, std::span<const std::uint8_t> bytes, std::int64_t t_ns, SourceLapCallback on_lap);
  // The end of the recording: every decoder's cut-off tail.
  void finish(SourceLapCallback on_lap);

  std::size_t size() const { return decoders_.size(); }
  // Null for a source without a profile.
  const ScanDecoder* decoder(std::size_t source) const { return decoders_.at(source).get(); }

 private:
  std::vector<std::unique_ptr<ScanDecoder>> decoders_;
};

}  // namespace ydscope
