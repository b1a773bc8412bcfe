#pragma once
// Test helper: read from a ByteLink until enough bytes arrived or the link ended, the way the
// session's read loop does, with a guard so a broken link fails the test instead of hanging it.
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include "core/link/byte_link.h"

namespace ydscope::test {

struct LinkReadResult {
  std::vector<std::uint8_t> bytes;
  boost::system::error_code end;  // set when the link reported an error or end of stream
};

inline LinkReadResult read_from_link(boost::asio::io_context& io, ByteLink& link, std::size_t want,
                                     std::size_t buffer_size,
                                     std::chrono::steady_clock::duration guard = std::chrono::seconds(10)) {
  LinkReadResult result;
  std::vector<std::uint8_t> buffer(buffer_size);
  // A link may hold a read with no asio work pending (a paused replay), so keep the context alive
  // until the read loop itself stops it.
  auto work = boost::asio::make_work_guard(io);
  std::function<void()> more = [&] {
    link.async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t n) {
      result.bytes.insert(result.bytes.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
      if (ec) {
        result.end = ec;
        io.stop();
      } else if (result.bytes.size() < want) {
        more();
      } else {
        io.stop();
      }
    });
  };
  more();
  io.restart();
  io.run_for(guard);
  return result;
}

}  // namespace ydscope::test
