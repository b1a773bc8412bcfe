// Three virtual lidars (G1, G6, TG30) on three pseudo-terminals at once, each with its own
// Session: every lap of each arrives whole and equal to what that lidar sent, a command to one
// reaches only that one, and unplugging one (its power goes too) leaves the other two scanning
// while it comes back by itself.
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "cli/fault_matrix_support.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

struct Received {
  std::mutex mutex;
  std::vector<LapSignature> laps;
  // [first, last] received-lap positions around a stop of this lidar's scan (a command, an
  // unplug): a lap the lidar closed just before it may be drained or lost in the port with it.
  std::vector<std::pair<std::size_t, std::size_t>> interruptions;
  std::size_t size() {
    std::lock_guard lock(mutex);
    return laps.size();
  }
  bool interrupted_at(std::size_t k) const {
    for (const auto& [first, last] : interruptions)
      if (k >= first && k <= last) return true;
    return false;
  }
};

LapSignature signature_of(const Lap& lap) {
  LapSignature signature;
  signature.points = lap.points.size();
  for (const LapPoint& point : lap.points) signature.range_sum += point.range_mm;
  return signature;
}

// Where each received lap is among the lidar's own laps (in order, each after the one before),
// or -1 for a lap that lidar never sent.
std::vector<long> positions_in_truth(const std::vector<TruthRecorder::TruthLap>& truth,
                                     const std::vector<LapSignature>& received) {
  std::vector<long> at;
  std::size_t from = 0;
  for (const LapSignature& lap : received) {
    long found = -1;
    for (std::size_t i = from; i < truth.size() && found < 0; ++i)
      if (!truth[i].touched && truth[i].signature.same_as(lap)) found = static_cast<long>(i);
    at.push_back(found);
    if (found >= 0) from = static_cast<std::size_t>(found) + 1;
  }
  return at;
}

// Waits (bounded) until `done` holds.
bool eventually(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + kPatience;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

TEST(SeveralLidars, ThreeAtOnceKeepTheirLapsTheirCommandsAndTheirFaultsApart) {
  const Model models[3] = {Model::G1, Model::G6, Model::TG30};
  // The truth first: the sims' threads call into it until the sims are gone.
  TruthRecorder truth[3];
  std::vector<std::unique_ptr<SimOnPty>> sims;
  for (int i = 0; i < 3; ++i) {
    sims.push_back(std::make_unique<SimOnPty>(models[i]));
    sims[i]->server().with_device(
        [&truth, i](VirtualLidar& d) { d.set_truth([&truth, i](const TruthPacket& p) { truth[i].add(p); }); });
  }
  Received received[3];
  std::vector<std::unique_ptr<Session>> sessions;
  for (int i = 0; i < 3; ++i) {
    sessions.push_back(std::make_unique<Session>(256));
    sessions[i]->connect(config_for(sims[i]->port()));  // model detected: each must find its own
  }
  // One consumer thread for the three lap rings, as a window draining every source would.
  std::atomic<bool> stop{false};
  std::thread consumer([&] {
    Lap lap;
    while (!stop.load()) {
      bool any = false;
      for (int i = 0; i < 3; ++i)
        while (sessions[i]->laps().try_pop(lap)) {
          std::lock_guard lock(received[i].mutex);
          received[i].laps.push_back(signature_of(lap));
          any = true;
        }
      if (!any) std::this_thread::sleep_for(2ms);
    }
  });
  const auto laps_beyond = [&](int i, std::size_t n) { return eventually([&] { return received[i].size() >= n; }); };

  for (int i = 0; i < 3; ++i) {
    const SessionSnapshot s = wait_for_state(*sessions[i], LinkState::Scanning);
    ASSERT_EQ(s.state, LinkState::Scanning) << describe_snapshot(s);
    ASSERT_TRUE(s.device && s.device->profile);
    EXPECT_EQ(s.device->profile->model, models[i]) << "source " << i << " found another lidar";
    EXPECT_TRUE(laps_beyond(i, 10)) << "source " << i;
  }

  // A command to one reaches that one only: the others' devices hear no byte meanwhile.
  for (int target = 0; target < 3; ++target) {
    std::uint64_t heard[3];
    for (int i = 0; i < 3; ++i) heard[i] = sims[i]->counters().server.bytes_in;
    const std::size_t first = received[target].size();
    const CommandResult result =
        run_command([&](CommandCallback done) { sessions[target]->refresh_health(std::move(done)); });
    EXPECT_TRUE(result.ok) << result.message;
    EXPECT_TRUE(laps_beyond(target, received[target].size() + 2));  // scanning again
    received[target].interruptions.push_back({first, received[target].size()});
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t now = sims[i]->counters().server.bytes_in;
      if (i == target)
        EXPECT_GT(now, heard[i]) << "the command never reached source " << i;
      else
        EXPECT_EQ(now, heard[i]) << "source " << target << "'s command reached source " << i;
    }
  }

  // Unplug the TG30: the G1 and the G6 scan on; the TG30 comes back when it is plugged in again.
  const std::size_t before[3] = {received[0].size(), received[1].size(), received[2].size()};
  sims[2]->server().unplug();
  EXPECT_TRUE(eventually([&] { return sessions[2]->snapshot().state != LinkState::Scanning; }));
  EXPECT_TRUE(laps_beyond(0, before[0] + 20));
  EXPECT_TRUE(laps_beyond(1, before[1] + 20));
  EXPECT_EQ(sessions[0]->snapshot().state, LinkState::Scanning);
  EXPECT_EQ(sessions[1]->snapshot().state, LinkState::Scanning);
  const std::size_t while_down = received[2].size();
  sims[2]->server().replug();
  EXPECT_EQ(wait_for_state(*sessions[2], LinkState::Scanning).state, LinkState::Scanning);
  received[2].interruptions.push_back({before[2], received[2].size()});
  EXPECT_TRUE(laps_beyond(2, while_down + 10));

  stop.store(true);
  consumer.join();
  for (auto& session : sessions) session->disconnect();

  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE("source " + std::to_string(i));
    std::lock_guard lock(received[i].mutex);
    const auto truth_laps = truth[i].laps();
    // A byte the virtual lidar could not write to its pty (its reader that far behind) changes a
    // lap without the truth knowing: said with any failure below.
    const std::uint64_t unheard = sims[i]->counters().server.bytes_unheard;
    SCOPED_TRACE("bytes the virtual lidar could not write to its pty: " + std::to_string(unheard));
    const auto at = positions_in_truth(truth_laps, received[i].laps);
    ASSERT_FALSE(at.empty());
    for (std::size_t k = 0; k < at.size(); ++k)
      ASSERT_GE(at[k], 0) << "lap " << k << " of " << at.size() << " (" << received[i].laps[k].points
                          << " points) is not a lap this lidar sent; laps before: " << (k > 0 ? at[k - 1] : -1)
                          << ", interrupted there: " << received[i].interrupted_at(k);
    // Whole runs: between two laps received in a row no lap the lidar sent went missing, except
    // where its scan was stopped.
    std::size_t gaps = 0;
    for (std::size_t k = 1; k < at.size(); ++k) {
      if (at[k] == at[k - 1] + 1) continue;
      ++gaps;
      EXPECT_TRUE(received[i].interrupted_at(k)) << "lap " << k << " came " << at[k] - at[k - 1] - 1
                                                 << " laps after the one before, while nothing stopped the scan";
    }
    EXPECT_LE(gaps, received[i].interruptions.size());
    EXPECT_EQ(sessions[i]->snapshot().queue_dropped, 0u);
  }
}

}  // namespace
}  // namespace ydscope
