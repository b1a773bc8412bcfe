#pragma once
// LinePacer: the device's serial line. Chunks of bytes (a reply, a scan packet) become ready at a
// time and leave one after another at the baud's pace, 10 bits per byte (8N1). drain(now) hands out
// only the bytes whose last bit has left the line by `now`, so a host reading at any moment sees
// exactly what a real UART would have delivered.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <span>
#include <vector>

namespace ydscope {

class LinePacer {
 public:
  static constexpr std::size_t kNoZeroEnd = std::numeric_limits<std::size_t>::max();
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

  explicit LinePacer(std::uint32_t baud);

  // Queues bytes ready at ready_ns (non-decreasing). zero_end: offset in `bytes` just past a zero
  // packet's last byte, reported by drain() so the server can time-stamp it. is_packet: count the
  // chunk in packets_sent() once its last byte is out.
  void enqueue(std::int64_t ready_ns, std::span<const std::uint8_t> bytes, std::size_t zero_end = kNoZeroEnd,
               bool is_packet = false);
  // Appends every byte fully sent by now_ns to out; zero_ends gets offsets in out (see enqueue).
  void drain(std::int64_t now_ns, std::vector<std::uint8_t>& out, std::vector<std::size_t>* zero_ends);
  // When the front chunk will have fully left the line; kNever when nothing is queued.
  std::int64_t next_completion_ns() const;
  // Drops every chunk that had not begun on the line by now_ns (the one in flight finishes).
  void drop_unstarted(std::int64_t now_ns);
  void clear();
  bool empty() const { return chunks_.empty(); }
  std::size_t queued_bytes() const { return bytes_.size(); }
  std::uint64_t packets_sent() const { return packets_sent_; }

 private:
  struct Chunk {
    std::int64_t ready_ns;
    std::size_t size;
    std::size_t sent;
    std::size_t zero_end;
    bool is_packet;
  };
  double ns_per_byte_;
  double line_free_ns_ = -1e300;  // when the last byte handed out finished
  std::deque<Chunk> chunks_;
  std::deque<std::uint8_t> bytes_;
  std::uint64_t packets_sent_ = 0;
};

}  // namespace ydscope
