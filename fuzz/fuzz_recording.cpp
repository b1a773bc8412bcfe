// Fuzzes the recording reader with arbitrary file contents, and decodes the device bytes it
// yields the way replay does (the recording's model and distance scale), so whatever a file can
// say reaches the decoder too.
// Checks besides "no crash, no sanitizer report":
// - every record's payload is at most kMaxRecordPayload and records advance through the file;
// - a record's source is one the reader knows (always 0 in version 1);
// - a read ends cleanly, truncated or corrupt, never two of them;
// - rewind() gives the same records again, and summarize_recording() agrees with the iteration;
// - metadata that parsed encodes and parses back to the same fields;
// - decoded ranges are finite and non-negative whatever the metadata claims.
#include <sys/mman.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_metadata.h"
#include "core/record/recording_reader.h"
#include "fuzz/fuzz_input.h"

namespace {

using namespace ydscope;

// The input as a file the reader can open by path, without touching the disk.
class MemoryFile {
 public:
  MemoryFile(const std::uint8_t* data, std::size_t size) : fd_(memfd_create("fuzz-recording", 0)) {
    FUZZ_CHECK(fd_ >= 0, "memfd_create failed");
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::write(fd_, data + done, size - done);
      FUZZ_CHECK(n > 0, "writing the memory file failed");
      done += static_cast<std::size_t>(n);
    }
  }
  ~MemoryFile() { ::close(fd_); }
  std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_;
};

struct Pass {
  std::uint64_t records = 0;
  std::uint64_t device_bytes = 0;
  std::uint64_t host_bytes = 0;
  std::int64_t last_t_ns = 0;
};

Pass read_all(RecordingReader& reader, ScanDecoder* decoder) {
  Pass pass;
  RecordView record;
  std::uint64_t last_offset = 0;
  while (reader.next(record)) {
    FUZZ_CHECK(record.payload.size() <= kMaxRecordPayload, "record payload above the format's limit");
    FUZZ_CHECK(pass.records == 0 || record.file_offset > last_offset, "records did not advance through the file");
    FUZZ_CHECK(record.source < kMaxRecordingSources && record.source < reader.source_count(),
               "a record of a source the reader does not know");
    FUZZ_CHECK(reader.version() >= kMultiSourceVersion || record.source == 0, "a version-1 record with a source");
    last_offset = record.file_offset;
    ++pass.records;
    pass.last_t_ns = record.t_ns;
    if (record.type == RecordType::DeviceToHost) {
      pass.device_bytes += record.payload.size();
      if (decoder) {
        decoder->feed(record.payload, record.t_ns, [](const Lap& lap) {
          for (const LapPoint& p : lap.points)
            FUZZ_CHECK(std::isfinite(p.range_mm) && p.range_mm >= 0.0f, "a recording's metadata made ranges invalid");
        });
      }
    }
    if (record.type == RecordType::HostToDevice) pass.host_bytes += record.payload.size();
  }
  FUZZ_CHECK(!(reader.truncated() && reader.corrupt()), "a read ended both truncated and corrupt");
  FUZZ_CHECK(reader.records_read() == pass.records, "records_read disagrees with the records returned");
  return pass;
}

void check_metadata_round_trip(const RecordingMetadata& metadata) {
  const RecordingMetadata again = RecordingMetadata::parse(metadata.encode());
  if (metadata.distance_scale && std::isnan(*metadata.distance_scale)) return;  // NaN never equals itself
  FUZZ_CHECK(again == metadata, "metadata does not survive encode and parse");
}

// Building a decoder costs a 64 Ki-entry correction table, so decoders are kept per (model,
// scale) and reset per input; a few dozen distinct scales are enough to keep the run fast.
ScanDecoder& decoder_for(const ModelProfile& profile, std::optional<double> scale) {
  // Keyed by the scale's bits: a NaN scale must find its decoder again, and NaN cannot be a map key.
  static std::map<std::pair<Model, std::optional<std::uint64_t>>, std::unique_ptr<ScanDecoder>> decoders;
  if (decoders.size() > 64) decoders.clear();
  std::optional<std::uint64_t> bits;
  if (scale) bits = std::bit_cast<std::uint64_t>(*scale);
  auto& slot = decoders[{profile.model, bits}];
  if (!slot) slot = std::make_unique<ScanDecoder>(profile, scale);
  slot->reset();
  return *slot;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const MemoryFile file(data, size);
  std::string error;
  auto reader = RecordingReader::open(file.path(), error);
  if (!reader) {
    FUZZ_CHECK(!error.empty(), "open failed without a sentence");
    return 0;
  }
  const ModelProfile* profile = reader->metadata().model ? find_profile(*reader->metadata().model) : nullptr;
  ScanDecoder& decoder = decoder_for(profile ? *profile : profile_for(Model::G6), reader->metadata().distance_scale);
  const Pass first = read_all(*reader, &decoder);
  for (std::size_t source = 0; source < reader->source_count(); ++source)
    check_metadata_round_trip(reader->source_metadata(source));

  reader->rewind();
  const Pass second = read_all(*reader, nullptr);
  FUZZ_CHECK(first.records == second.records && first.device_bytes == second.device_bytes,
             "rewind did not give the same records again");

  const auto summary = summarize_recording(file.path(), error);
  FUZZ_CHECK(summary.has_value(), "summary failed on a file that opened");
  FUZZ_CHECK(summary->records == first.records && summary->device_bytes == first.device_bytes &&
                 summary->host_bytes == first.host_bytes,
             "summary disagrees with reading the records");
  return 0;
}
