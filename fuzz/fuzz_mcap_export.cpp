// Fuzzes the MCAP writer's input path: a recording's records (link bytes both ways, metadata
// text with any model, scale or start time) into McapRecordingExport, written to memory, then
// read back by the tests' strict MCAP reader (tests/export/mcap_test_reader.h), which checks
// every CRC, index and offset independently of the writer.
// Input: byte 0 picks the chunk compression (bits 0-1) and the chunk size (64 << bits 2-5 bytes,
// so chunks close often); then records, each: u8 type, u8 time step (its cube in microseconds, so
// times stay non-decreasing as the recording reader guarantees, with large jumps), u16 LE payload
// length (cut to what is left), payload.
// Checks besides "no crash, no sanitizer report":
// - finishing succeeds and the file reads back complete, CRCs and indexes right;
// - the summary's statistics match the messages found, and the writer's own count;
// - every message is on an advertised channel, logged inside its chunk's time range.
#include <cstdint>
#include <exception>
#include <span>
#include <string>

#include "core/export/mcap_recording_export.h"
#include "core/export/mcap_sink.h"
#include "fuzz/fuzz_input.h"
#include "tests/export/mcap_test_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ydscope;
  if (size < 1) return 0;
  McapExportOptions options;
  options.mcap.compression = static_cast<ChunkCompression>((data[0] & 3) % 3);
  options.mcap.chunk_size = std::size_t{64} << ((data[0] >> 2) & 15);
  McapMemorySink sink;
  McapRecordingExport exporter(sink, options);

  std::int64_t t_ns = 0;
  std::size_t at = 1;
  while (at + 4 <= size) {
    const std::uint8_t type = data[at];
    const std::int64_t step = data[at + 1];
    const std::size_t length = std::min<std::size_t>(data[at + 2] | (data[at + 3] << 8), size - at - 4);
    at += 4;
    t_ns += step * step * step * 1000;
    exporter.record(static_cast<RecordType>(type), std::span(data + at, length), t_ns);
    at += length;
    if (type == 0xFF) FUZZ_CHECK(exporter.flush(), "a flush failed");
  }
  FUZZ_CHECK(exporter.finish(), exporter.error().c_str());

  test::McapContents file;
  try {
    file = test::read_mcap(sink.bytes());
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, e.what());
  }
  FUZZ_CHECK(file.complete, "the finished file has no valid footer");
  FUZZ_CHECK(file.stat_messages == file.messages.size(), "statistics count other messages than the chunks hold");
  FUZZ_CHECK(exporter.statistics().message_count == file.messages.size(), "the writer counted other messages");
  FUZZ_CHECK(file.stat_chunks == file.chunks && file.chunk_indexes == file.chunks, "a chunk without its index");
  for (const test::ReadMessage& message : file.messages)
    FUZZ_CHECK(file.channels.count(message.channel_id) == 1, "a message on a channel never advertised");
  return 0;
}
