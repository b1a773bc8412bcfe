#include "core/record/recording_writer.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace ydscope {
namespace {

constexpr std::size_t kBufferSize = std::size_t{64} * 1024;

std::string write_error_sentence(const std::string& path, const std::string& what, int errno_value) {
  std::string sentence = "cannot " + what + " " + path + ": " + std::strerror(errno_value);
  if (errno_value == ENOSPC) sentence += "; free some disk space and record again";
  if (errno_value == EACCES || errno_value == EROFS) sentence += "; choose a folder you can write to";
  if (errno_value == ENOENT) sentence += "; check that the folder exists";
  return sentence;
}

}  // namespace

std::string recording_output_problem(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode))
      return "cannot record to " + path + ": it is a folder; give a file name such as " +
             (std::filesystem::path(path) / "bench.ydrec").string();
    if (!S_ISREG(info.st_mode))
      return "cannot record to " + path + ": it is not a regular file (a device or a pipe), and a recording " +
             "must be read back; give a file name such as bench.ydrec";
    return {};
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  if (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    return "cannot record to " + path + ": the folder " + folder + " does not exist; create it or choose another";
  if (::access(folder.c_str(), W_OK) != 0)
    return "cannot record to " + path + ": the folder " + folder + " is not writable; choose a folder you can write to";
  return {};
}

RecordingWriter::RecordingWriter(std::FILE* file, std::string path, std::int64_t start_ns, std::size_t sources)
    : file_(file), path_(std::move(path)), start_ns_(start_ns), sources_(sources) {}

RecordingWriter::~RecordingWriter() { close(); }

std::unique_ptr<RecordingWriter> RecordingWriter::create(const std::string& path, RecordingMetadata metadata,
                                                         std::int64_t start_ns, std::string& error) {
  std::vector<RecordingMetadata> sources;
  sources.push_back(std::move(metadata));
  return create_sources(path, std::move(sources), start_ns, error);
}

std::unique_ptr<RecordingWriter> RecordingWriter::create_sources(const std::string& path,
                                                                 std::vector<RecordingMetadata> sources,
                                                                 std::int64_t start_ns, std::string& error) {
  if (sources.empty() || sources.size() > kMaxRecordingSources) {
    error = "cannot record " + std::to_string(sources.size()) + " sources to " + path + ": from 1 to " +
            std::to_string(kMaxRecordingSources) + " fit in one recording";
    return nullptr;
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    error = write_error_sentence(path, "create recording", errno);
    return nullptr;
  }
  std::setvbuf(file, nullptr, _IOFBF, kBufferSize);
  std::unique_ptr<RecordingWriter> writer(new RecordingWriter(file, path, start_ns, sources.size()));
  const auto header = encode_file_header(sources.size() == 1 ? kRecordingVersion : kMultiSourceVersion);
  if (std::fwrite(header.data(), 1, header.size(), file) != header.size()) {
    error = write_error_sentence(path, "write recording", errno);
    return nullptr;
  }
  writer->file_size_ = header.size();
  const std::string now = iso8601_utc_now();  // one t=0 for every source
  for (std::size_t id = 0; id < sources.size(); ++id) {
    if (!sources[id].start_wall_time) sources[id].start_wall_time = now;
    if (!writer->update_metadata(sources[id], start_ns, static_cast<std::uint16_t>(id))) {
      error = writer->error();
      return nullptr;
    }
  }
  return writer;
}

bool RecordingWriter::append(Direction direction, std::span<const std::uint8_t> bytes, std::int64_t t_ns,
                             std::uint16_t source) {
  if (bytes.empty()) return !failed() && file_ != nullptr;
  if (!write_record(static_cast<RecordType>(direction), bytes, t_ns, source)) return false;
  (direction == Direction::DeviceToHost ? device_bytes_ : host_bytes_) += bytes.size();
  if (last_t_ns_ - last_flush_t_ns_ >= kFlushInterval) return flush();
  return true;
}

bool RecordingWriter::update_metadata(const RecordingMetadata& changes, std::int64_t t_ns, std::uint16_t source) {
  const std::string text = changes.encode();
  const std::span<const std::uint8_t> payload(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  if (!write_record(RecordType::Metadata, payload, t_ns, source)) return false;
  sources_[source].merge(changes);
  return flush();
}

bool RecordingWriter::known_source(std::uint16_t source) {
  if (source < sources_.size()) return true;
  error_ = "cannot write source " + std::to_string(source) + " to " + path_ + ", which records " +
           std::to_string(sources_.size()) + (sources_.size() == 1 ? " source" : " sources");
  return false;
}

bool RecordingWriter::write_record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns,
                                   std::uint16_t source) {
  if (!file_ || failed() || !known_source(source)) return false;
  // A read larger than the format allows is split, keeping every byte.
  while (payload.size() > kMaxRecordPayload) {
    if (!write_record(type, payload.first(kMaxRecordPayload), t_ns, source)) return false;
    payload = payload.subspan(kMaxRecordPayload);
  }
  RecordHeader header;
  header.type = static_cast<std::uint8_t>(type);
  header.source = source;
  header.length = static_cast<std::uint32_t>(payload.size());
  header.t_ns = std::max(last_t_ns_, t_ns - start_ns_);
  const auto head = encode_record_header(header);
  if (std::fwrite(head.data(), 1, head.size(), file_) != head.size() ||
      std::fwrite(payload.data(), 1, payload.size(), file_) != payload.size()) {
    fail("write recording", errno);
    return false;
  }
  last_t_ns_ = header.t_ns;
  file_size_ += head.size() + payload.size();
  ++records_;
  return true;
}

bool RecordingWriter::flush() {
  if (!file_ || failed()) return false;
  if (std::fflush(file_) != 0) {
    fail("write recording", errno);
    return false;
  }
  last_flush_t_ns_ = last_t_ns_;
  return true;
}

bool RecordingWriter::close() {
  if (!file_) return !failed();
  const bool flushed = failed() || std::fflush(file_) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(file_) == 0;
  const int close_errno = errno;
  file_ = nullptr;
  if (!failed() && !flushed) fail("write recording", flush_errno);
  if (!failed() && !closed) fail("close recording", close_errno);
  return !failed();
}

std::uint64_t RecordingWriter::bytes(Direction direction) const {
  return direction == Direction::DeviceToHost ? device_bytes_ : host_bytes_;
}

void RecordingWriter::fail(const std::string& what, int errno_value) {
  error_ = write_error_sentence(path_, what, errno_value);
}

}  // namespace ydscope
