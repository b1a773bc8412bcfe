// The MCAP export of the shown laps writes what is on screen: the laps the view holds, oldest
// first, each as one /scan and one /points message logged at its close time on the wall clock
// and stamped at its first ray's,
// every point exactly; and the Record tab's names for .ydrec, .mcap or both.
#include "ui/view/export/lap_mcap.h"
#include "ui/view/export/whole_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "export/point_cloud_reader.h"
#include "support/temp_dir.h"
#include "ui/view/export/file_names.h"

namespace ydscope::ui {
namespace {

std::vector<std::uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Lap lap_of(std::uint64_t index, std::int64_t rx_ns, std::size_t points) {
  Lap lap;
  lap.index = index;
  lap.first_rx_ns = rx_ns - 100'000'000;
  lap.last_rx_ns = rx_ns;
  for (std::size_t i = 0; i < points; ++i)
    lap.points.push_back({static_cast<float>(i) * 1.5f, 1000.0f + static_cast<float>(index * 10 + i), PointFlag::None});
  return lap;
}

TEST(LapMcap, WritesEveryShownLapOldestFirstWithEveryPoint) {
  LapHistory history(4);
  for (std::uint64_t i = 1; i <= 6; ++i) history.push(lap_of(i, static_cast<std::int64_t>(i) * 125'000'000, 10 + i));
  const test::TempDir dir("shown-laps");
  const std::string path = dir.file("shown.mcap");
  RecordingMetadata metadata;
  metadata.model = "G6";
  const std::int64_t to_wall = 1'800'000'000'000'000'000;
  const ShownLapsMcap saved = save_shown_laps_mcap(history, 10, Model::G6, metadata, to_wall, path);
  ASSERT_TRUE(saved.error.empty()) << saved.error;
  EXPECT_FALSE(std::filesystem::exists(part_name(path))) << "the part it was written as is left behind";
  EXPECT_EQ(saved.laps, 4u) << "all the view holds, not more";
  EXPECT_EQ(saved.messages, 9u);  // four /scan, four /points, one /tf_static

  const auto contents = test::read_mcap(file_bytes(path));
  ASSERT_TRUE(contents.complete);
  EXPECT_EQ(contents.profile, "ros2");
  EXPECT_EQ(contents.stat_messages, 9u);  // and /tf_static: where the lidar sits (ros_tf.h)
  EXPECT_NE(test::channel_on(contents, "/tf_static"), 0);
  const std::uint16_t scan = test::channel_on(contents, "/scan"), points = test::channel_on(contents, "/points");
  ASSERT_NE(scan, 0);
  ASSERT_NE(points, 0);
  std::vector<std::uint64_t> cloud_times;
  std::size_t scans = 0;
  for (const auto& m : contents.messages) {
    if (m.channel_id == scan) ++scans;
    if (m.channel_id != points) continue;
    // Laps 3..6, oldest first, every point as the view holds it.
    const HistoryLap& shown = history.at_age(3 - cloud_times.size());
    const auto cloud = test::point_cloud_points(m.data);
    ASSERT_EQ(cloud.size(), shown.points.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      EXPECT_EQ(cloud[i].angle_deg, shown.points[i].angle_deg);
      EXPECT_FLOAT_EQ(cloud[i].range_m, shown.points[i].range_mm / 1000.0f);
    }
    cloud_times.push_back(m.log_time);
    EXPECT_EQ(test::point_cloud(m.data).stamp_ns, static_cast<std::uint64_t>(to_wall + shown.first_rx_ns))
        << "stamped at the lap's first ray, logged at its closing byte";
  }
  EXPECT_EQ(scans, 4u);
  EXPECT_EQ(cloud_times,
            (std::vector<std::uint64_t>{
                static_cast<std::uint64_t>(to_wall + 375'000'000), static_cast<std::uint64_t>(to_wall + 500'000'000),
                static_cast<std::uint64_t>(to_wall + 625'000'000), static_cast<std::uint64_t>(to_wall + 750'000'000)}));
  ASSERT_FALSE(contents.metadata.empty());
  EXPECT_EQ(contents.metadata.back().at("model"), "G6");
}

TEST(LapMcap, AFileThatCannotBeCreatedIsOneSentence) {
  LapHistory history(2);
  history.push(lap_of(1, 1'000'000'000, 3));
  const ShownLapsMcap saved = save_shown_laps_mcap(history, 2, Model::G1, {}, 0, "/nonexistent-dir/x.mcap");
  EXPECT_NE(saved.error.find("/nonexistent-dir/x.mcap"), std::string::npos) << saved.error;
  EXPECT_EQ(saved.error.find(".part"), std::string::npos) << "names a file the user never asked for: " << saved.error;
  EXPECT_EQ(saved.error.find('\n'), std::string::npos);
}

TEST(RecordingPaths, OneNameForEachFormat) {
  EXPECT_EQ(recording_paths(RecordFormat::Ydrec, "run.ydrec").ydrec, "run.ydrec");
  EXPECT_EQ(recording_paths(RecordFormat::Ydrec, "run.ydrec").mcap, "");
  EXPECT_EQ(recording_paths(RecordFormat::Mcap, "run.mcap").mcap, "run.mcap");
  EXPECT_EQ(recording_paths(RecordFormat::Mcap, "run.mcap").ydrec, "");
  // Both: the MCAP beside the .ydrec, whichever was typed.
  for (const std::string typed : {"out/run.ydrec", "out/run.mcap"}) {
    const RecordingPaths both = recording_paths(RecordFormat::Both, typed);
    EXPECT_EQ(both.ydrec, "out/run.ydrec") << typed;
    EXPECT_EQ(both.mcap, "out/run.mcap") << typed;
  }
}

TEST(RecordingPaths, EmptyMeansTimestampedNamesThatOverwriteNothing) {
  const test::TempDir temp("recording-names");
  const std::filesystem::path& dir = temp.path();
  const RecordingPaths first = recording_paths(RecordFormat::Both, "", dir);
  EXPECT_EQ(std::filesystem::path(first.ydrec).extension(), ".ydrec");
  EXPECT_EQ(std::filesystem::path(first.mcap).extension(), ".mcap");
  EXPECT_EQ(std::filesystem::path(first.mcap).parent_path(), dir);
  std::ofstream(first.mcap) << "x";
  const RecordingPaths second = recording_paths(RecordFormat::Mcap, "", dir);
  EXPECT_NE(second.mcap, first.mcap);
  EXPECT_FALSE(std::filesystem::exists(second.mcap));
}

}  // namespace
}  // namespace ydscope::ui
