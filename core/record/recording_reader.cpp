#include "core/record/recording_reader.h"

#include <sys/types.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string_view>

namespace ydscope {
namespace {

bool known_type(std::uint8_t type) {
  return type == static_cast<std::uint8_t>(RecordType::DeviceToHost) ||
         type == static_cast<std::uint8_t>(RecordType::HostToDevice) ||
         type == static_cast<std::uint8_t>(RecordType::Metadata);
}

}  // namespace

RecordingReader::RecordingReader(std::FILE* file, std::string path) : file_(file), path_(std::move(path)) {}

RecordingReader::~RecordingReader() {
  if (file_) std::fclose(file_);
}

std::unique_ptr<RecordingReader> RecordingReader::open(const std::string& path, std::string& error) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    error = "cannot open recording " + path + ": " + std::strerror(errno);
    return nullptr;
  }
  std::unique_ptr<RecordingReader> reader(new RecordingReader(file, path));
  std::array<std::uint8_t, kFileHeaderSize> head{};
  const std::size_t got = std::fread(head.data(), 1, head.size(), file);
  const auto header = got == head.size() ? parse_file_header(head) : std::nullopt;
  if (!header) {
    error = path + " is not a ydscope recording (no YDSCOPE-REC header)";
    return nullptr;
  }
  if (header->version > kRecordingVersion) {
    error = path + " is a version " + std::to_string(header->version) +
            " recording; this ydscope reads version " + std::to_string(kRecordingVersion) + ", update ydscope";
    return nullptr;
  }
  reader->version_ = header->version;
  reader->first_record_offset_ = header->header_size;
  reader->rewind();
  // Merge the leading metadata record now so metadata() is useful before iterating; then start
  // over so callers still see every record, metadata included.
  RecordView first;
  reader->next(first);
  reader->rewind();
  return reader;
}

void RecordingReader::rewind() {
  ::fseeko(file_, static_cast<off_t>(first_record_offset_), SEEK_SET);
  offset_ = first_record_offset_;
  records_read_ = 0;
  warning_.clear();
  error_.clear();
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
    out.t_ns = header.t_ns;
    out.payload = payload_;
    out.file_offset = record_offset;
    if (out.type == RecordType::Metadata) {
      const std::string_view text(reinterpret_cast<const char*>(payload_.data()), payload_.size());
      metadata_.merge(RecordingMetadata::parse(text, &metadata_warnings_));
    }
    return true;
  }
}

bool is_recording_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  std::array<std::uint8_t, kRecordingMagic.size()> head{};
  const bool ok = std::fread(head.data(), 1, head.size(), file) == head.size() && is_recording(head);
  std::fclose(file);
  return ok;
}

std::optional<RecordingSummary> summarize_recording(const std::string& path, std::string& error) {
  auto reader = RecordingReader::open(path, error);
  if (!reader) return std::nullopt;
  RecordingSummary summary;
  RecordView record;
  while (reader->next(record)) {
    ++summary.records;
    summary.duration_ns = record.t_ns;
    if (record.type == RecordType::DeviceToHost) summary.device_bytes += record.payload.size();
    if (record.type == RecordType::HostToDevice) summary.host_bytes += record.payload.size();
  }
  summary.metadata = reader->metadata();
  summary.warning = reader->warning();
  summary.error = reader->error();
  return summary;
}

}  // namespace ydscope
