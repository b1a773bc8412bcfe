#pragma once
// How long the I/O thread may hold off reading a scan stream. Every chunk the port delivers costs
// a wake-up (a context switch, the dominant cost of the I/O thread), yet the consumer only needs
// the bytes when a lap closes. So mid-lap the session stops watching the port for a while and
// reads everything that piled up in one go, waking for each chunk only near the lap's end.
#include <chrono>

#include "core/protocol/lap_end_forecast.h"

namespace ydscope {

struct ReadHoldInputs {
  std::int64_t now_ns = 0;        // on the clock of the forecast's times
  LapEndOutlook lap_end;          // the decoder's forecast
  double stream_bytes_per_s = 0;  // what the stream has been delivering (0: unknown)
  double line_bytes_per_s = 0;    // the most the link can deliver (0: unbounded)
};

// Zero when reading should go on at once: no line limit, a stream faster than the line's baud (the
// port is not the line it says), or a hold too short to pay for itself.
// Otherwise until the lap is due to close (less its slack), or the least time the forecast bytes
// need if that is longer: all but one packet (which may come as one burst) at line rate, or at the
// stream's average rate with a margin. Never so long that, at full line rate, what piles up (a
// packet already waiting, the hold, a timer firing late) reaches the point where n_tty throttles
// the driver, with a margin: a USB bridge would lose bytes from there on.
std::chrono::nanoseconds read_hold(const ReadHoldInputs& in);

}  // namespace ydscope
