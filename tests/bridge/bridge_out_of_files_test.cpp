// Out of file descriptors, the server cannot accept: it keeps serving the clients it has, and
// accepts the waiting connections once descriptors are free again. (The limit is this test
// process's own; ctest runs each test in a process of its own.)
#include <sys/resource.h>

#include <algorithm>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <gtest/gtest.h>

#include "bridge/bridge_test_support.h"
#include "bridge/lidar_feed.h"

namespace ydscope::test {
namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

TEST(BridgeOutOfFiles, WaitingConnectionsAreAcceptedOnceDescriptorsAreFree) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // UBSan's vptr check probes memory through a pipe: with no descriptor free it reports a
  // false "invalid vptr" and cannot print its report either.
  GTEST_SKIP() << "sanitizer runtimes need file descriptors, which this test takes away";
#endif
  auto server = start_server();
  LidarFeed feed(*server, 2.0);
  ScanCollector steady(server->port());
  ASSERT_TRUE(steady.subscribed());

  // Sockets made first, so connecting them needs no descriptor in this process, only accepting.
  asio::io_context io;
  std::vector<tcp::socket> waiting;
  int highest = 0;
  for (int i = 0; i < 4; ++i) {
    waiting.emplace_back(io);
    waiting.back().open(tcp::v4());
    highest = std::max(highest, waiting.back().native_handle());
  }
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &saved), 0);
  rlimit tight = saved;
  tight.rlim_cur = static_cast<rlim_t>(highest + 1);
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &tight), 0);
  for (auto& socket : waiting) socket.connect({asio::ip::make_address("127.0.0.1"), server->port()});
  // Laps keep flowing to the steady client while the server cannot accept.
  const bool laps_flowed = feed.wait_for_scans(feed.scan_times().size() + 10, 60s);
  const std::size_t clients_meanwhile = server->clients().size();
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &saved), 0);
  EXPECT_TRUE(laps_flowed);
  EXPECT_EQ(clients_meanwhile, 1u) << "the server accepted with no descriptor free?";

  EXPECT_TRUE(eventually([&] { return server->clients().size() == 1 + waiting.size(); }))
      << "the waiting connections were not accepted once descriptors were free";
  ASSERT_TRUE(feed.wait_for_scans(feed.scan_times().size() + 15, 60s));
  const std::uint64_t last = feed.scan_times().back();
  steady.finish_at(last);
  expect_every_lap(steady, feed.scan_times(), last);
  expect_still_serving(server->port());
}

}  // namespace
}  // namespace ydscope::test
