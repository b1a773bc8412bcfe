#include "core/record/recording_reader.h"

#include <sys/stat.h>
#include <sys/types.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace ydscope {
namespace {

bool known_type(std::uint8_t type) {
  return type == static_cast<std::uint8_t>(RecordType::DeviceToHost) ||
         type == static_cast<std::uint8_t>(RecordType::HostToDevice) ||
         type == static_cast<std::uint8_t>(RecordType::Metadata);
}

// "2.500 s", "1e+09 s": readable whatever the size of the damage.
std::string seconds_text(double ns) {
  char text[48];
  const double seconds = ns / 1e9;
  std::snprintf(text, sizeof text, seconds < 1e6 ? "%.3f s" : "%.3g s", seconds);
  return text;
}

// One sentence for a file header this reader cannot use (empty when it can), and its kind.
// `got` bytes of `head` were read from a file of `file_size` bytes.
std::string header_problem(const std::string& path, const std::array<std::uint8_t, kFileHeaderSize>& head,
                           std::size_t got, std::uint64_t file_size, RecordingOpenFailure& kind) {
  kind = RecordingOpenFailure::NotARecording;
  if (got == 0) return path + " is empty, not a ydscope recording";
  const std::size_t magic_bytes = std::min(got, kRecordingMagic.size());
  if (!std::equal(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(magic_bytes), kRecordingMagic.begin()))
    return path + " is not a ydscope recording (no YDSCOPE-REC header)";
  if (got < kFileHeaderSize)
    return path + " ends after " + std::to_string(got) + " bytes, inside its " + std::to_string(kFileHeaderSize) +
           "-byte file header: the recording was cut off before anything was recorded";
  const auto header = parse_file_header(head);
  kind = RecordingOpenFailure::Unsupported;
  const std::string reads = "this ydscope reads versions " + std::to_string(kRecordingVersion) + " and " +
                            std::to_string(kMultiSourceVersion);
  if (header->version == 0)
    return path + " says it is a version 0 recording, which does not exist (" + reads + "): the file is damaged";
  if (header->version > kMultiSourceVersion)
    return path + " is a version " + std::to_string(header->version) + " recording; " + reads + ", update ydscope";
  const bool past_end = header->header_size > file_size;
  if (header->header_size < kFileHeaderSize || header->header_size > kMaxFileHeaderSize || past_end)
    return path + " has an impossible file-header size of " + std::to_string(header->header_size) + " bytes" +
           (past_end ? " in a " + std::to_string(file_size) + "-byte file" : "") + " (version " +
           std::to_string(kRecordingVersion) + " writes " + std::to_string(kFileHeaderSize) + "): the file is damaged";
  return {};
}

}  // namespace

RecordingReader::RecordingReader(std::FILE* file, std::string path) : file_(file), path_(std::move(path)) {}

RecordingReader::~RecordingReader() {
  if (file_) std::fclose(file_);
}

std::unique_ptr<RecordingReader> RecordingReader::open(const std::string& path, std::string& error,
                                                       RecordingOpenFailure* failure) {
  RecordingOpenFailure kind = RecordingOpenFailure::Unreadable;
  const auto fail = [&](std::string sentence) {
    error = std::move(sentence);
    if (failure) *failure = kind;
    return nullptr;
  };
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    return fail(path + " is a folder; pass a recording file (.ydrec) instead");
  kind = RecordingOpenFailure::NotARecording;
  if (std::string problem = not_a_regular_file(path); !problem.empty()) return fail(std::move(problem));
  kind = RecordingOpenFailure::Unreadable;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return fail("cannot open recording " + path + ": " + std::strerror(errno));
  std::unique_ptr<RecordingReader> reader(new RecordingReader(file, path));
  std::array<std::uint8_t, kFileHeaderSize> head{};
  const std::size_t got = std::fread(head.data(), 1, head.size(), file);
  if (std::ferror(file)) return fail("cannot read recording " + path + ": " + std::strerror(errno));
  // Only a regular file has a size to hold the header size against.
  const bool sized = ::fstat(::fileno(file), &info) == 0 && S_ISREG(info.st_mode);
  const auto file_size = sized ? static_cast<std::uint64_t>(info.st_size) : UINT64_MAX;
  if (std::string problem = header_problem(path, head, got, file_size, kind); !problem.empty())
    return fail(std::move(problem));
  const auto header = parse_file_header(head);
  reader->version_ = header->version;
  reader->first_record_offset_ = header->header_size;
  reader->rewind();
  // Merge the leading metadata records now (one, or one per source in version 2) so metadata()
  // is useful before iterating; then start over so callers still see every record.
  RecordView first;
  while (reader->next(first) && first.type == RecordType::Metadata && reader->version_ >= kMultiSourceVersion) {
  }
  reader->rewind();
  return reader;
}

void RecordingReader::rewind() {
  ::fseeko(file_, static_cast<off_t>(first_record_offset_), SEEK_SET);
  offset_ = first_record_offset_;
  records_read_ = 0;
  warning_.clear();
  error_.clear();
  last_t_ns_ = time_anchor_file_ns_ = time_anchor_ns_ = 0;
  time_corrections_ = 0;
  first_time_problem_.clear();
}

std::int64_t RecordingReader::checked_time(std::int64_t file_t_ns, std::uint64_t record_offset) {
  // Overflow-checked: a damaged time may be anything, INT64_MIN included.
  std::int64_t since_anchor = 0;
  std::int64_t t_ns = 0;
  const bool representable = !__builtin_sub_overflow(file_t_ns, time_anchor_file_ns_, &since_anchor) &&
                             !__builtin_add_overflow(time_anchor_ns_, since_anchor, &t_ns);
  if (representable && t_ns >= last_t_ns_ && t_ns - last_t_ns_ <= kMaxRecordGapNs) {
    last_t_ns_ = t_ns;
    return t_ns;
  }
  if (time_corrections_++ == 0) {
    // In double: the step itself may not fit in 64 bits.
    const double step = static_cast<double>(file_t_ns) - static_cast<double>(time_anchor_file_ns_) -
                        static_cast<double>(last_t_ns_ - time_anchor_ns_);
    first_time_problem_ = "the record at byte " + std::to_string(record_offset) +
                          (step < 0 ? " goes back " + seconds_text(-step) + " in time"
                                    : " jumps " + seconds_text(step) + " ahead (more than " +
                                          std::to_string(kMaxRecordGapNs / 1'000'000'000) + " s)");
  }
  // Re-anchor: this record plays right after the previous one, the next ones keep their spacing.
  time_anchor_file_ns_ = file_t_ns;
  time_anchor_ns_ = last_t_ns_;
  return last_t_ns_;
}

std::string RecordingReader::time_warning() const {
  if (time_corrections_ == 0) return {};
  const std::string count = time_corrections_ == 1 ? "" : " (" + std::to_string(time_corrections_) + " such records)";
  return path_ + " has damaged record times: " + first_time_problem_ + count +
         "; each plays right after the record before it, and the ones after keep their spacing";
}

bool RecordingReader::next(RecordView& out) {
  if (!warning_.empty() || !error_.empty()) return false;
  for (;;) {
    std::array<std::uint8_t, kRecordHeaderSize> head{};
    const std::size_t got = std::fread(head.data(), 1, head.size(), file_);
    if (got == 0) return false;  // clean end
    const std::string at = " at byte " + std::to_string(offset_);
    const std::string intact = "; the " + std::to_string(records_read_) + " records before it are intact";
    if (got < head.size()) {
      warning_ = path_ + " ends inside a record header" + at + " (the recorder was probably stopped abruptly)" + intact;
      return false;
    }
    const RecordHeader header = parse_record_header(head);
    if (header.type == 0 || header.length > kMaxRecordPayload) {
      error_ = path_ + " is corrupt" + at + " (record type " + std::to_string(header.type) + ", length " +
               std::to_string(header.length) + ")" + intact;
      return false;
    }
    // Version 1 leaves the field reserved: whatever it holds, there is one source.
    const std::uint16_t source = version_ >= kMultiSourceVersion ? header.source : 0;
    if (source >= kMaxRecordingSources) {
      error_ = path_ + " is corrupt" + at + " (source " + std::to_string(source) + "; at most " +
               std::to_string(kMaxRecordingSources) + " sources)" + intact;
      return false;
    }
    payload_.resize(header.length);
    if (std::fread(payload_.data(), 1, header.length, file_) != header.length) {
      warning_ = path_ + " ends inside a record" + at + " (the recorder was probably stopped abruptly)" + intact;
      return false;
    }
    const std::uint64_t record_offset = offset_;
    offset_ += kRecordHeaderSize + header.length;
    if (!known_type(header.type)) continue;  // a later version's record: skip it
    ++records_read_;
    out.type = static_cast<RecordType>(header.type);
    out.t_ns = checked_time(header.t_ns, record_offset);
    out.payload = payload_;
    out.file_offset = record_offset;
    out.source = source;
    if (source >= sources_.size()) sources_.resize(source + 1u);
    // Each metadata record is merged once: after a rewind, an early record must not undo a
    // later one, nor repeat its warnings.
    if (out.type == RecordType::Metadata && record_offset >= metadata_merged_to_) {
      const std::string_view text(reinterpret_cast<const char*>(payload_.data()), payload_.size());
      sources_[source].merge(RecordingMetadata::parse(text, &metadata_warnings_));
      metadata_merged_to_ = offset_;
    }
    return true;
  }
}

std::vector<std::string> RecordingReader::damage() const {
  std::vector<std::string> sentences;
  if (corrupt()) sentences.push_back(error_);
  if (truncated()) sentences.push_back(warning_);
  if (time_corrections_ > 0) sentences.push_back(time_warning());
  for (const std::string& field : metadata_warnings_) sentences.push_back(path_ + ": " + field);
  return sentences;
}

std::string not_a_regular_file(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || S_ISREG(info.st_mode) || S_ISDIR(info.st_mode)) return {};
  const char* kind = S_ISFIFO(info.st_mode) ? "a FIFO (named pipe)" : S_ISSOCK(info.st_mode) ? "a socket" : "a device";
  return path + " is " + kind + ", not a file; ydscope reads a recording more than once, so save it to a file first";
}

bool is_recording_file(const std::string& path) {
  if (!not_a_regular_file(path).empty()) return false;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  std::array<std::uint8_t, kRecordingMagic.size()> head{};
  const bool ok = std::fread(head.data(), 1, head.size(), file) == head.size() && is_recording(head);
  std::fclose(file);
  return ok;
}

std::optional<RecordingSummary> summarize_recording(const std::string& path, std::string& error,
                                                    RecordingOpenFailure* failure) {
  auto reader = RecordingReader::open(path, error, failure);
  if (!reader) return std::nullopt;
  RecordingSummary summary;
  summary.version = reader->version();
  RecordView record;
  while (reader->next(record)) {
    ++summary.records;
    summary.duration_ns = record.t_ns;
    if (record.source >= summary.sources.size()) summary.sources.resize(record.source + 1u);
    SourceSummary& source = summary.sources[record.source];
    if (record.type == RecordType::DeviceToHost) {
      summary.device_bytes += record.payload.size();
      source.device_bytes += record.payload.size();
    }
    if (record.type == RecordType::HostToDevice) {
      summary.host_bytes += record.payload.size();
      source.host_bytes += record.payload.size();
    }
  }
  summary.sources.resize(std::max(summary.sources.size(), reader->source_count()));
  for (std::size_t i = 0; i < summary.sources.size(); ++i)
    summary.sources[i].metadata = i < reader->source_count() ? reader->source_metadata(i) : RecordingMetadata{};
  summary.metadata = reader->metadata();
  summary.warning = reader->warning();
  summary.error = reader->error();
  summary.time_warning = reader->time_warning();
  summary.metadata_warnings = reader->metadata_warnings();
  summary.damage = reader->damage();
  return summary;
}

}  // namespace ydscope
