// The app's Share and Record with two virtual lidars: both cover every lidar shown, not only the
// selected one. A Foxglove client gets /G1/scan and /G6/scan (each in its own frame) and
// /tf_static; --record both writes one version-2 .ydrec with each lidar's bytes under its name
// and one MCAP with each lidar's laps under its name.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <set>

#include "app_test_support.h"
#include "core/record/recording_reader.h"
#include "export/laser_scan_reader.h"
#include "export/point_cloud_reader.h"
#include "private_display.h"
#include "share_client.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// The file with `extension` in `dir`, or empty after `timeout`.
std::filesystem::path file_in(const std::filesystem::path& dir, const std::string& extension,
                              std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == extension) return entry.path();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return {};
}

TEST(AppSeveralOutputs, ShareServesEveryLidarShown) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  const std::uint16_t port = free_port();
  ASSERT_NE(port, 0);
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-share-several");
  const pid_t app =
      spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G1,G6", "--share", "--share-port", std::to_string(port)});

  auto client = connect_to(port, std::chrono::seconds(40));
  ASSERT_TRUE(client) << "nothing served on 127.0.0.1:" << port;
  EXPECT_NE(client->channel_of("/tf_static"), 0u) << "two lidars' poses are not on /tf_static";
  ASSERT_TRUE(client->subscribe(1, "/G1/scan")) << "the first lidar is not served";
  ASSERT_TRUE(client->subscribe(2, "/G6/scan")) << "the second lidar is not served";
  std::map<std::uint32_t, ScanSeen> seen;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (seen.size() < 2 && std::chrono::steady_clock::now() < deadline)
    if (const auto message = client->read_binary(std::chrono::seconds(5)))
      seen.emplace(message->subscription, laser_scan(message->payload));
  ASSERT_EQ(seen.size(), 2u) << "a scan came from only one of the two lidars";
  EXPECT_EQ(seen.at(1).frame_id, "G1");
  EXPECT_EQ(seen.at(2).frame_id, "G6");
  EXPECT_FLOAT_EQ(seen.at(2).range_max, 25.0f) << "the G6's range, so the G6's laps";
  EXPECT_NE(seen.at(1).range_max, seen.at(2).range_max) << "both scans came from one lidar";

  EXPECT_EQ(stop_process(app, SIGTERM), 0) << "quitting while shared";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(AppSeveralOutputs, RecordWritesEveryLidarShownIntoEachFile) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-record-several");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G1,G6", "--record", "both"});
  const auto ydrec = file_in(dir, ".ydrec", std::chrono::seconds(40));
  const auto mcap = file_in(dir, ".mcap", std::chrono::seconds(5));
  ASSERT_FALSE(ydrec.empty()) << "no .ydrec from --record both";
  ASSERT_FALSE(mcap.empty()) << "no .mcap from --record both";
  // Until each lidar has a few laps' bytes in the .ydrec (it is readable while it grows).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
  for (;;) {
    std::string error;
    const auto growing = summarize_recording(ydrec.string(), error);
    if (growing && growing->sources.size() == 2 && growing->sources[0].device_bytes > 20000 &&
        growing->sources[1].device_bytes > 20000)
      break;
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the lidars' bytes did not reach the .ydrec";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  ASSERT_EQ(stop_process(app, SIGTERM), 0);

  std::string error;
  const auto summary = summarize_recording(ydrec.string(), error);
  ASSERT_TRUE(summary) << error;
  EXPECT_EQ(summary->version, 2) << "two lidars make a version-2 recording";
  ASSERT_EQ(summary->sources.size(), 2u);
  EXPECT_EQ(summary->sources[0].metadata.name, "G1");
  EXPECT_EQ(summary->sources[1].metadata.name, "G6");
  EXPECT_EQ(summary->sources[0].metadata.model, "G1");
  EXPECT_EQ(summary->sources[1].metadata.model, "G6");
  // Both lidars' bytes up to the end, each under its own source id.
  EXPECT_GT(summary->sources[0].device_bytes, 20000u);
  EXPECT_GT(summary->sources[1].device_bytes, 20000u);

  std::ifstream in(mcap, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const McapContents contents = read_mcap(bytes);
  EXPECT_TRUE(contents.complete) << "quitting left the MCAP without its summary";
  for (const char* topic : {"/G1/points", "/G6/points", "/G1/scan", "/G6/scan"}) {
    const std::uint16_t channel = channel_on(contents, topic);
    ASSERT_NE(channel, 0u) << topic << " is not in the MCAP";
    EXPECT_GE(contents.stat_channel_counts.at(channel), 3u) << topic << " holds too few laps";
  }
  EXPECT_NE(channel_on(contents, "/tf_static"), 0u);
  EXPECT_EQ(channel_on(contents, "/scan"), 0u) << "several lidars are named apart";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
