// The SnapshotBoard: what the I/O thread posts, others read and wait for.
#include "core/session/snapshot_board.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

namespace ydscope {
namespace {

using namespace std::chrono_literals;

TEST(SnapshotBoard, AWaiterWakesOnThePostThatSatisfiesIt) {
  SnapshotBoard board;
  std::thread io([&] {
    board.set_state(LinkState::Connecting, "opening");
    board.set_state(LinkState::Scanning, "");
  });
  const auto scanning = [](const SessionSnapshot& s) { return s.state == LinkState::Scanning; };
  // The bound is only a hang guard: the post ends the wait.
  const SessionSnapshot seen = board.wait_until([&] { return board.read(); }, scanning, 30s);
  io.join();
  EXPECT_EQ(seen.state, LinkState::Scanning);
  EXPECT_EQ(board.state(), LinkState::Scanning);
}

TEST(SnapshotBoard, AWaitThatIsNeverSatisfiedReturnsTheLastSnapshotAtItsTimeout) {
  SnapshotBoard board;
  board.set_state(LinkState::Probing, "asking");
  const SessionSnapshot seen =
      board.wait_until([&] { return board.read(); }, [](const SessionSnapshot&) { return false; }, 50ms);
  EXPECT_EQ(seen.state, LinkState::Probing);
  EXPECT_EQ(seen.message, "asking");
}

TEST(SnapshotBoard, AResultIsPostedBeforeItsCallerHearsOfItAndACallerThatThrowsIsContained) {
  SnapshotBoard board;
  board.publish([](SessionSnapshot& s) {
    s.busy = true;
    s.busy_what = "read health";
  });
  CommandResult result;
  result.ok = true;
  result.what = "read health";
  bool posted_first = false;
  board.post_result(result, [&](const CommandResult& heard) {
    const SessionSnapshot s = board.read();
    posted_first = !s.busy && s.busy_what.empty() && s.last_result && s.last_result->what == heard.what;
    throw std::runtime_error("a caller's bug");
  });
  EXPECT_TRUE(posted_first);
  EXPECT_NO_THROW(board.post_result(result, nullptr));
}

}  // namespace
}  // namespace ydscope
