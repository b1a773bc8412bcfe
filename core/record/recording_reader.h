#pragma once
// RecordingReader: iterates the records of a .ydrec file (format in recording_format.h), one at
// a time from disk, so hours of recording cost one record of memory. A file cut off inside its
// last record (the writer was killed) reads every complete record and then reports a warning;
// a corrupt record stops the iteration with an error sentence.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/record/recording_format.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

struct RecordView {
  RecordType type = RecordType::DeviceToHost;
  std::int64_t t_ns = 0;                  // since the recording started; checked (see time_warning())
  std::span<const std::uint8_t> payload;  // valid until the next call to next() or rewind()
  std::uint64_t file_offset = 0;          // of the record header, for messages
  std::uint16_t source = 0;               // version 2: whose record; always 0 in version 1
};

// Why a recording did not open. The CLI exits 2 (usage) for Unsupported: the file is a
// recording, but of a version or header this ydscope cannot read, and retrying will not help.
enum class RecordingOpenFailure : std::uint8_t {
  Unreadable,     // missing, no permission, a folder, a read error
  NotARecording,  // no magic, or cut off inside the file header
  Unsupported,    // unknown version, impossible header size
};

class RecordingReader {
 public:
  // Checks the magic, version and header size. Null plus one sentence in `error` (and the kind
  // in `failure`, when given) saying what is really wrong: a missing file, a folder, a file that
  // is not a recording, one cut off inside its header, an unknown version, a damaged header.
  static std::unique_ptr<RecordingReader> open(const std::string& path, std::string& error,
                                               RecordingOpenFailure* failure = nullptr);
  ~RecordingReader();
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  // The next record of a known type (metadata records are returned too, and merged into
  // metadata()). False at the end of the file, at a truncated tail (see warning()) or at a
  // corrupt record (see error()).
  bool next(RecordView& out);
  // Back to the first record (metadata() keeps what was merged so far).
  void rewind();

  // Metadata merged from every metadata record read so far (open() reads the leading ones): of
  // source 0, which is the only one of a version-1 file.
  const RecordingMetadata& metadata() const { return sources_.front(); }
  // Version 2: every source's, by id (open() has read each one's first metadata record). A
  // version-1 file has one source.
  std::size_t source_count() const { return sources_.size(); }
  const RecordingMetadata& source_metadata(std::size_t source) const { return sources_.at(source); }
  // Damaged metadata fields that were skipped.
  const std::vector<std::string>& metadata_warnings() const { return metadata_warnings_; }
  bool truncated() const { return !warning_.empty(); }
  // "... ends inside a record at byte N (the recorder was probably killed); the K records before it are intact"
  const std::string& warning() const { return warning_; }
  bool corrupt() const { return !error_.empty(); }
  // Record times that went backwards or jumped more than kMaxRecordGapNs ahead, found so far:
  // one sentence naming the first and how many there were; empty when every time was sound.
  // Such records are returned at the previous record's time, later ones keep their spacing.
  std::string time_warning() const;
  std::uint64_t time_corrections() const { return time_corrections_; }
  const std::string& error() const { return error_; }
  // Everything above that was found wrong but still reads, one sentence each: a corrupt record or
  // a cut-off tail, damaged record times, damaged metadata fields ("PATH: ..."). Empty when sound.
  std::vector<std::string> damage() const;
  std::uint16_t version() const { return version_; }
  const std::string& path() const { return path_; }
  std::uint64_t records_read() const { return records_read_; }

 private:
  RecordingReader(std::FILE* file, std::string path);
  // The file's time of a record, mapped onto a timeline that never goes back nor jumps.
  std::int64_t checked_time(std::int64_t file_t_ns, std::uint64_t record_offset);

  std::FILE* file_;
  std::string path_;
  std::uint16_t version_ = 0;
  std::uint64_t first_record_offset_ = kFileHeaderSize;
  std::uint64_t offset_ = 0;
  std::uint64_t records_read_ = 0;
  std::vector<std::uint8_t> payload_;
  std::vector<RecordingMetadata> sources_{1};
  std::uint64_t metadata_merged_to_ = 0;  // file offset up to which metadata records are merged
  std::vector<std::string> metadata_warnings_;
  std::string warning_;
  std::string error_;
  // checked_time(): file time `time_anchor_file_ns_` reads as `time_anchor_ns_`; the others follow it.
  std::int64_t last_t_ns_ = 0;
  std::int64_t time_anchor_file_ns_ = 0;
  std::int64_t time_anchor_ns_ = 0;
  std::uint64_t time_corrections_ = 0;
  std::string first_time_problem_;
};

// True when the file at `path` starts with the recording magic (false if it cannot be read, and
// for anything but a regular file, which is not opened: a FIFO would block and lose its bytes).
bool is_recording_file(const std::string& path);

// One sentence when `path` exists but is not a regular file (a FIFO, a device, a socket): a
// recording is read more than once (planned, then played) and a FIFO that never writes would block
// without a word. Empty for a regular file, and for a path that does not exist.
std::string not_a_regular_file(const std::string& path);

// One source's part of a recording.
struct SourceSummary {
  RecordingMetadata metadata;
  std::uint64_t device_bytes = 0;
  std::uint64_t host_bytes = 0;
};

// Totals of a whole recording, read in one pass (metadata fully merged).
struct RecordingSummary {
  RecordingMetadata metadata;          // source 0's
  std::vector<SourceSummary> sources;  // by id; one for a version-1 file
  std::uint16_t version = 0;
  std::uint64_t records = 0;
  std::uint64_t device_bytes = 0;
  std::uint64_t host_bytes = 0;
  std::int64_t duration_ns = 0;                // time of the last record
  std::string warning;                         // truncated tail
  std::string error;                           // corrupt record
  std::string time_warning;                    // damaged record times (RecordingReader::time_warning())
  std::vector<std::string> metadata_warnings;  // damaged metadata fields that were skipped
  std::vector<std::string> damage;             // all of the above as sentences (RecordingReader::damage)
};
std::optional<RecordingSummary> summarize_recording(const std::string& path, std::string& error,
                                                    RecordingOpenFailure* failure = nullptr);

}  // namespace ydscope
