// Fuzzes the command-reply side: ReplyReader over arbitrary chunks, then every payload parser on
// what it found and on raw slices of the input.
// Input: byte 0 chooses the chunking, byte 1 the reader's junk limit, the rest are device bytes.
// Checks besides "no crash, no sanitizer report":
// - feed() never claims more bytes than it was given, and stops right after a complete reply;
// - a complete single reply's payload has exactly the header's length, never above kMaxReplyPayload;
// - the reader gives up only past its junk limit;
// - every parser that accepts a payload encodes it back to the same bytes.
#include <array>
#include <cstdint>
#include <span>

#include "core/protocol/commands.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/reply.h"
#include "core/protocol/reply_reader.h"
#include "fuzz/fuzz_input.h"

namespace {

using namespace ydscope;

template <std::size_t N>
bool same_bytes(const std::array<std::uint8_t, N>& encoded, std::span<const std::uint8_t> payload) {
  return payload.size() == N && std::equal(encoded.begin(), encoded.end(), payload.begin());
}

void parse_every_payload(std::span<const std::uint8_t> payload) {
  if (const auto info = parse_device_info(payload)) {
    FUZZ_CHECK(same_bytes(encode_device_info(*info), payload), "device info does not round-trip");
    FUZZ_CHECK(serial_string(*info).size() <= 2 * info->serial.size(), "serial text longer than its bytes allow");
  }
  if (const auto health = parse_health(payload)) {
    FUZZ_CHECK(same_bytes(encode_health(*health), payload), "health does not round-trip");
    if (const auto status = device_status(health->status)) (void)device_status_name(*status);
    for (unsigned bit = 0; bit < 8; ++bit) (void)g1_health_bit_name(bit);
  }
  if (const auto frequency = parse_scan_frequency(payload)) {
    FUZZ_CHECK(same_bytes(encode_scan_frequency(*frequency), payload), "scan frequency does not round-trip");
  }
  if (const auto value = parse_one_byte(payload)) {
    FUZZ_CHECK(same_bytes(encode_one_byte(*value), payload), "one-byte answer does not round-trip");
  }
  for (const ModelProfile& profile : all_profiles()) {
    if (const auto khz = parse_ranging_khz(profile, payload)) {
      FUZZ_CHECK(profile.ranging_index(*khz).has_value(), "ranging kHz outside the model's table");
    }
  }
  if (const auto on = parse_power_down_protection(payload)) {
    FUZZ_CHECK(same_bytes(encode_power_down_protection(*on), payload), "power-down protection does not round-trip");
  }
  if (const auto on = parse_low_power(payload)) {
    FUZZ_CHECK(same_bytes(encode_low_power(*on), payload), "low power does not round-trip");
  }
  if (const auto direction = parse_motor_direction(payload)) {
    FUZZ_CHECK(same_bytes(encode_motor_direction(*direction), payload), "motor direction does not round-trip");
  }
  if (const auto on = parse_constant_frequency(payload)) {
    FUZZ_CHECK(same_bytes(encode_constant_frequency(*on), payload), "constant frequency does not round-trip");
  }
  (void)parse_module_status(payload);
}

void check_reply(const ReplyReader& reader) {
  const ReplyHeader& header = reader.header();
  FUZZ_CHECK(header.mode == ReplyMode::Single || header.mode == ReplyMode::Continuous, "reply mode not defined");
  if (header.mode == ReplyMode::Single) {
    FUZZ_CHECK(reader.payload().size() == header.length, "payload size differs from the header's length");
  }
  FUZZ_CHECK(reader.payload().size() <= kMaxReplyPayload, "payload larger than any command answers");
  for (int code = 0; code < 256; ++code) {
    if (const auto command = command_from_code(static_cast<std::uint8_t>(code))) {
      if (reply_matches(header, *command) && header.mode == ReplyMode::Single) {
        FUZZ_CHECK(reader.payload().size() == reply_spec(*command).payload_length, "matched reply of the wrong size");
      }
    }
  }
  parse_every_payload(reader.payload());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const fuzz::Chunker chunker(data[0]);
  const std::size_t max_junk = data[1] * 16u;
  const std::span<const std::uint8_t> stream(data + 2, size - 2);

  ReplyReader reader(max_junk);
  fuzz::for_each_chunk(stream, chunker, [&](std::span<const std::uint8_t> chunk) {
    while (!chunk.empty()) {
      const std::size_t used = reader.feed(chunk);
      FUZZ_CHECK(used <= chunk.size(), "feed used more bytes than it was given");
      chunk = chunk.subspan(used);
      if (reader.state() == ReplyReader::State::Searching) {
        FUZZ_CHECK(chunk.empty(), "reader stopped while still searching");
        break;
      }
      if (reader.complete()) check_reply(reader);
      if (reader.state() == ReplyReader::State::GaveUp) {
        FUZZ_CHECK(reader.junk_bytes() > max_junk, "reader gave up inside its junk limit");
      }
      reader.reset();  // as the sequencer does after each reply or give-up
    }
  });

  // The parsers on their own, on the first bytes of the input at every length a reply can have.
  for (std::size_t n = 0; n <= std::min(stream.size(), kMaxReplyPayload); ++n) parse_every_payload(stream.first(n));
  if (stream.size() >= kReplyHeaderSize) {
    if (const auto header = parse_reply_header(stream.first(kReplyHeaderSize))) {
      FUZZ_CHECK(header->length <= kReplyLengthMask, "header length wider than 30 bits");
      std::array<std::uint8_t, kReplyHeaderSize> raw{};
      std::copy_n(stream.begin(), kReplyHeaderSize, raw.begin());
      FUZZ_CHECK(encode_reply_header(*header) == raw, "reply header does not round-trip");
    }
  }
  return 0;
}
