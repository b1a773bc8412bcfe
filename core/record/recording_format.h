#pragma once
// The ydscope recording file (.ydrec): every byte that crossed the link, both directions, with
// its receive/send time, plus the session's metadata. Append-only, so a program killed mid-way
// leaves a readable file; plain C++ (no Boost) so the decoder CLI and tests can read it.
//
// Layout (all integers little-endian; format versions 1 and 2, which differ only where said):
//
//   File header, 16 bytes
//     0  12  magic "YDSCOPE-REC" followed by one 0x00 byte
//    12   2  u16 format version: 1 one source, 2 several (see "Sources" below)
//    14   2  u16 header size in bytes (16); readers skip to this offset, so later versions may
//            append header fields without breaking version-1 readers
//
//   Then records, back to back, until the end of the file. Record header, 16 bytes:
//     0   1  u8  type: 1 device->host bytes, 2 host->device bytes, 3 metadata
//     1   1  u8  flags, 0 (readers ignore them)
//     2   2  u16 version 1: reserved, 0 (readers ignore it); version 2: the source id, below
//            kMaxRecordingSources (a larger one is corruption)
//     4   4  u32 payload length in bytes, at most 1 MiB (kMaxRecordPayload)
//     8   8  i64 time in nanoseconds since the recording started, from a monotonic clock
//            (steady clock: never jumps with wall-clock changes); non-decreasing in a file.
//            Readers check: a time before the previous record's, or more than kMaxRecordGapNs
//            after it, is damage; it is read as the previous time (later records keep their
//            spacing from it) and reported as a warning, so a bad time never stalls a replay.
//    16   n  payload
//
//   Type 1 / 2 payload: the bytes exactly as read from / written to the link, one record per
//   read or write (a record is not a packet: packets span records and records span packets).
//   Type 3 payload: UTF-8 text, one "key=value\n" line per field. The first record of every
//   file is a metadata record; later metadata records add or replace keys (e.g. the device
//   info that arrives after the recording started). In values, "\\" stands for a backslash and
//   "\n" for a newline. Keys of version 1 (all optional):
//     model            model name: G1, G6, TG15, TG30, TG50
//     baud             line rate of the port, decimal
//     distance_scale   mm per distance count used while recording, decimal
//     port             the --port text: /dev/ttyUSB0, tcp://host:port
//     start_wall_time  UTC wall-clock time of t=0, ISO 8601 "2026-11-22T02:20:00.123Z"
//     model_code       device-info model byte, decimal
//     firmware         device-info firmware "major.minor"
//     hardware         device-info hardware version, decimal
//     serial           device-info serial number as text
//     software         the program that wrote the file, "ydscope 0.1.0"
//   Keys of version 2, in each source's metadata (see below; optional as well):
//     name             what the user called the source: "front", "g1" (--name)
//     pose             where it sits in the common frame, "x,y,yaw[,flip]" (core/frame/pose.h)
//   Unknown keys are kept and shown, never an error.
//
//   Sources (version 2): one file holds several lidars recorded at once, each a source with its
//   own id (0, 1, ...) in every record's header and its own metadata: a metadata record says
//   what the source of its header is, and later ones of that source add or replace keys. The
//   file starts with one metadata record per source, in id order, all at t=0, so a reader knows
//   every source before the first link byte. Times are one timeline for the whole file (every
//   source's records in time order). Writers write version 1 when there is one source, so a
//   single lidar's file reads as it always did; version 2 only when there are several.
//
//   Readers skip records of unknown types (their length says how far), so new types can be
//   added without a version change. A length above kMaxRecordPayload or a type of 0 means the
//   file is corrupt from that record on. A file that ends inside a record (the writer was
//   killed) is truncated: every earlier record is valid, and readers say so as a warning.
//
// Durability: the writer flushes its buffer to the kernel at least every 100 ms of recorded
// time and on every metadata record, so a killed program loses at most that much; a power cut
// may lose what the kernel had not written to disk yet (no fsync on the I/O thread).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace ydscope {

inline constexpr std::array<std::uint8_t, 12> kRecordingMagic = {'Y', 'D', 'S', 'C', 'O', 'P',
                                                                 'E', '-', 'R', 'E', 'C', 0};
// The version of one source's file, and of several sources' (the newest; readers read both).
inline constexpr std::uint16_t kRecordingVersion = 1;
inline constexpr std::uint16_t kMultiSourceVersion = 2;
// Version 2's source ids run from 0 up to this, exclusive.
inline constexpr std::uint16_t kMaxRecordingSources = 64;
inline constexpr std::size_t kFileHeaderSize = 16;
// Room a later version-1 writer may take for more header fields; a larger size is damage.
inline constexpr std::size_t kMaxFileHeaderSize = 4096;
inline constexpr std::size_t kRecordHeaderSize = 16;
inline constexpr std::uint32_t kMaxRecordPayload = 1u << 20;
// The longest silence between two records a reader takes as real. While its link is up a
// recording session writes something every few seconds at most (a stall is declared after 2 s
// and the reconnect sends commands); a longer gap (a cable left unplugged for minutes, or a
// damaged time such as 1e18) is played on without the pause.
inline constexpr std::int64_t kMaxRecordGapNs = 60'000'000'000;
// Suggested file name extension.
inline constexpr const char* kRecordingExtension = ".ydrec";

enum class RecordType : std::uint8_t {
  DeviceToHost = 1,  // bytes the lidar sent (scan stream, replies)
  HostToDevice = 2,  // bytes we sent (commands)
  Metadata = 3,      // key=value text
};
// Which way link bytes went; the values are the record types.
enum class Direction : std::uint8_t { DeviceToHost = 1, HostToDevice = 2 };

struct RecordHeader {
  std::uint8_t type = 0;  // raw, so unknown types survive parsing
  std::uint8_t flags = 0;
  std::uint32_t length = 0;
  std::int64_t t_ns = 0;
  std::uint16_t source = 0;  // version 2 (bytes 2-3); the reserved 0 of version 1
};

// True when `first_bytes` starts with the magic (needs at least its 12 bytes).
bool is_recording(std::span<const std::uint8_t> first_bytes);

std::array<std::uint8_t, kFileHeaderSize> encode_file_header(std::uint16_t version = kRecordingVersion);
// The version and header size of a file header as written; empty when the magic does not match.
// Readers check both (see kMaxFileHeaderSize).
struct FileHeader {
  std::uint16_t version = 0;
  std::uint16_t header_size = 0;
};
std::optional<FileHeader> parse_file_header(std::span<const std::uint8_t, kFileHeaderSize> bytes);

std::array<std::uint8_t, kRecordHeaderSize> encode_record_header(const RecordHeader& header);
RecordHeader parse_record_header(std::span<const std::uint8_t, kRecordHeaderSize> bytes);

}  // namespace ydscope
