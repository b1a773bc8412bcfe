#pragma once
// LapEndForecast: when the next lap can close, judged from the rhythm of the packets seen so far,
// in bytes (how much can still arrive first) and in time (when laps have been closing). The
// session uses it to stop watching the port mid-lap and read what piled up in one go, yet be
// awake when the closing zero packet's last byte arrives (see core/session/read_hold.h).
//
// The byte forecast errs early: it counts only packets that, at the current angular stride, end
// well before the previous zero packet's angle comes round again, and then the smallest possible
// zero packet (one sample; G1's LastCRC byte in front of it only adds to the real distance).
// Without a rhythm to go on (start-up, junk) it falls back to "the packet in progress plus the
// smallest zero packet", or 1. The time forecast
// is the last close plus the lap period, with a slack that grows with the period's jitter. A
// stream that breaks rhythm costs latency on a lap, never bytes.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/protocol/packet_decoder.h"

namespace ydscope {

struct LapEndOutlook {
  std::size_t bytes = 1;            // bytes that can arrive before a lap could close (at least 1)
  std::size_t packet_bytes = 0;     // the size of an ordinary packet, 0 until the stream has shown it
  std::int64_t next_close_ns = 0;   // when the next lap should close (rx clock), 0 when unknown
  std::int64_t close_slack_ns = 0;  // how early it might close all the same
};

class LapEndForecast {
 public:
  // Every valid packet, in stream order.
  void observe(const PacketView& packet);
  // Forgets the rhythm (a new stream).
  void reset();

  // `partial` is the packet in progress as the framer holds it (starting at its AA), empty at a
  // packet boundary.
  LapEndOutlook outlook(std::span<const std::uint8_t> partial) const;

 private:
  // Bytes that can follow a packet starting at `fsa_degrees` before a lap could close: the whole
  // packets that still end clear of the lap end, then the smallest zero packet.
  std::size_t bytes_after_packet_at(double fsa_degrees) const;
  std::size_t bytes_to_wait(std::span<const std::uint8_t> partial) const;
  void observe_close(std::int64_t rx_ns);

  // What the packets so far have shown; angles in degrees.
  struct Rhythm {
    bool have_last = false;  // a packet has been observed
    bool last_was_zero = false;
    double last_fsa = 0;
    std::size_t last_size = 0;  // bytes
    bool have_zero = false;     // a zero packet has been observed: its angle is where laps close
    double zero_fsa = 0;
    double stride_degrees = 0;       // angle one ordinary packet advances, 0 until one was followed
    std::size_t stride_bytes = 0;    // that packet's size
    std::int64_t last_close_ns = 0;  // receive time of the last zero packet
    double period_ns = 0;            // smoothed time between zero packets, 0 until two were seen
    double jitter_ns = 0;            // smoothed distance of a period from the estimate
  };

  Rhythm rhythm_{};
};

}  // namespace ydscope
