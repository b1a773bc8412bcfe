#include "app/cli/lap_json.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <stdexcept>

#include "core/export/lap_text.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {

JsonOut::~JsonOut() {
  try {
    flush();
  } catch (...) {
  }
}

namespace {
[[noreturn]] void throw_write_failed() {
  throw std::runtime_error("writing the output failed: " + std::string(std::strerror(errno)));
}

// Writes `text` to `fd` in pieces that never block, waiting for room in short polls, until it is
// written or, with no room, `give_up` is set. A signal alone cannot be trusted to break a blocked
// write: one that had written part of its bytes returns that count and stdio writes the rest,
// blocking again. PIPE_BUF bytes fit once poll says a pipe has room.
void write_until(int fd, std::string_view text, const std::atomic<bool>& give_up) {
  while (!text.empty()) {
    pollfd room{fd, POLLOUT, 0};
    const int ready = ::poll(&room, 1, /*ms=*/100);
    if (ready > 0) {
      const ssize_t written = ::write(fd, text.data(), std::min<std::size_t>(text.size(), PIPE_BUF));
      if (written > 0) {
        text.remove_prefix(static_cast<std::size_t>(written));
        continue;
      }
      if (written < 0 && errno != EINTR && errno != EAGAIN) throw_write_failed();
    } else if (ready < 0 && errno != EINTR) {
      throw_write_failed();
    }
    if (give_up.load()) throw std::runtime_error("writing the output was given up: its reader took nothing");
  }
}
}  // namespace

void JsonOut::flush() {
  if (text_.empty()) return;
  const std::string_view text = text_;
  try {
    if (give_up_) {
      if (std::fflush(file_) != 0) throw_write_failed();  // nothing of stdio's may come after ours
      write_until(::fileno(file_), text, *give_up_);
    } else if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0) {
      // fflush too: stdout on a pipe is fully buffered, and a reader must get each line we hand over.
      throw_write_failed();
    }
  } catch (...) {
    text_.clear();
    throw;
  }
  text_.clear();
}

namespace {
void write_type(JsonObject& line, std::string_view type, std::optional<std::string_view> source) {
  line.field("type", type);
  if (source) line.field("source", *source);
}

std::optional<bool> crc_ok(CrcVerdict crc) {
  if (crc == CrcVerdict::Ok) return true;
  if (crc == CrcVerdict::Mismatch) return false;
  return std::nullopt;
}
}  // namespace

void write_lap(JsonOut& out, const Lap& lap, std::optional<std::uint8_t> health, double t_s,
               std::optional<std::string_view> source) {
  {
    JsonObject line(out.buffer());
    write_type(line, "lap", source);
    line.field("index", lap.index).field("t", t_s, 6);
    {
      JsonArray points = line.array("points");
      for (const LapPoint& point : lap.points) {
        std::string& text = points.item_text();
        text.push_back('[');
        append_point_fields(text, point);
        text.push_back(']');
      }
    }
    // G1's CT channel, or the zero packet's CT of a G6/TG read as the field reads it.
    line.field("scan_hz", lap.ct_info_trusted() ? lap.scan_hz : std::nullopt, 2);
    line.field("health", health).field("crc_ok", crc_ok(lap.crc));
    line.field("packets", lap.packets).field("checksum_errors", lap.checksum_errors);
    // only a damaged stream: a sound lap's line stays as it was
    if (lap.cut_points > 0) line.field("cut_points", lap.cut_points);
  }
  out.raw("\n");
  out.maybe_flush();
}

void write_summary(JsonOut& out, const DecoderCounters& counters, const std::optional<std::string>& start,
                   std::optional<std::string_view> source) {
  {
    JsonObject line(out.buffer());
    write_summary_fields(line, counters, start, source);
  }
  out.raw("\n");
}

void write_summary_fields(JsonObject& line, const DecoderCounters& c, const std::optional<std::string>& start,
                          std::optional<std::string_view> source) {
  write_type(line, "summary", source);
  line.field("bytes", c.bytes).field("packets", c.packets).field("checksum_errors", c.checksum_errors);
  line.field("zero_packets", c.zero_packets).field("laps", c.laps);
  if (c.overflow_points > 0) line.field("cut_points", c.overflow_points);
  if (start) line.field("start", *start);
}

}  // namespace ydscope::cli
