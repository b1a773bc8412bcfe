// The app's MCAP files, read back with the tests' own MCAP reader. Recording in both formats at
// once, the MCAP's /points hold exactly the laps the .ydrec's bytes decode to, and the file is
// complete (summary and footer) after quitting. Exporting the shown laps (M) writes one /scan
// and one /points per lap the view holds: frozen, the same laps and points as the CSV export (E).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "app_test_support.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_reader.h"
#include "export/point_cloud_reader.h"
#include "private_display.h"
#include "x11_input.h"
#include "support/field_decoder.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

std::vector<std::uint8_t> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A file with `extension` in `dir` that is not in `seen` (then added), or empty after `timeout`; it
// is whole once it has its name (ui/view/export/whole_file.h). `poke` runs before each look (a key tap
// that asks for the file).
template <class Poke>
std::filesystem::path new_file(const std::filesystem::path& dir, const std::string& extension,
                               std::set<std::string>& seen, std::chrono::seconds timeout, Poke poke) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    poke();
    for (int i = 0; i < 20; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != extension || seen.count(entry.path().filename().string())) continue;
        seen.insert(entry.path().filename().string());
        return entry.path();
      }
    }
  }
  return {};
}

// The /points messages of an MCAP file, in order.
std::vector<std::vector<CloudPoint>> clouds_in(const McapContents& contents) {
  const std::uint16_t points = channel_on(contents, "/points");
  std::vector<std::vector<CloudPoint>> clouds;
  for (const auto& m : contents.messages)
    if (m.channel_id == points) clouds.push_back(point_cloud_points(m.data));
  return clouds;
}

// /points holds a lap's returns: a sample without one is no point.
bool same_points(const std::vector<CloudPoint>& cloud, const Lap& lap) {
  const std::vector<LapPoint> returns = returns_of(lap.points);
  if (cloud.size() != returns.size()) return false;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud[i].angle_deg != returns[i].angle_deg || cloud[i].range_m != returns[i].range_mm / 1000.0f) return false;
  return true;
}

TEST(AppMcap, RecordingBothFormatsGivesTheSameLapsInEach) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-record-mcap");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6", "--record", "both"});
  std::set<std::string> seen;
  const auto mcap = new_file(dir, ".mcap", seen, std::chrono::seconds(40), [] {});
  const auto ydrec = new_file(dir, ".ydrec", seen, std::chrono::seconds(5), [] {});
  ASSERT_FALSE(mcap.empty()) << "no .mcap from --record both";
  ASSERT_FALSE(ydrec.empty()) << "no .ydrec from --record both";
  EXPECT_EQ(mcap.stem(), ydrec.stem()) << "one timestamped name for both";
  std::this_thread::sleep_for(std::chrono::seconds(4));  // ~30 laps of the virtual G6
  ASSERT_EQ(stop_process(app, SIGTERM), 0);

  std::string error;
  auto reader = RecordingReader::open(ydrec.string(), error);
  ASSERT_TRUE(reader) << error;
  std::vector<Lap> laps;
  ScanDecoder decoder = test::field_decoder(Model::G6);
  RecordView record;
  while (reader->next(record))
    if (record.type == RecordType::DeviceToHost)
      decoder.feed(record.payload, record.t_ns, [&](const Lap& lap) { laps.push_back(lap); });

  const McapContents contents = read_mcap(file_bytes(mcap));
  EXPECT_TRUE(contents.complete) << "quitting left the MCAP without its summary";
  const auto clouds = clouds_in(contents);
  ASSERT_GE(clouds.size(), 10u);
  EXPECT_EQ(contents.stat_channel_counts.at(channel_on(contents, "/scan")), clouds.size());
  // The MCAP's tap started a moment after the .ydrec: its laps are a run of the .ydrec's laps. When
  // the app starts slowly (a loaded machine) the lidar is already turning, and both taps may open
  // within one lap: the MCAP then begins with that lap whole (the session saw all of it), of which
  // the .ydrec holds only the end, as a lap cut short or none.
  const auto lap_of_ydrec = [&](const std::vector<CloudPoint>& cloud) {
    std::size_t at = 0;
    while (at < laps.size() && !same_points(cloud, laps[at])) ++at;
    return at;
  };
  std::size_t skipped = 0, first = lap_of_ydrec(clouds[0]);
  if (first == laps.size()) {
    skipped = 1;
    first = lap_of_ydrec(clouds[1]);
    ASSERT_LT(first, laps.size()) << "neither of the MCAP's first two laps is a lap of the .ydrec";
    ASSERT_LE(first, 1u) << "the MCAP's first lap is not a lap of the .ydrec, nor the one it joined partway";
    if (first == 1) {
      const std::vector<LapPoint> end = returns_of(laps[0].points);
      ASSERT_LT(end.size(), clouds[0].size()) << "the .ydrec's first lap is not part of the MCAP's first";
      const std::size_t from = clouds[0].size() - end.size();
      for (std::size_t i = 0; i < end.size(); ++i)
        ASSERT_EQ(clouds[0][from + i].angle_deg, end[i].angle_deg) << "the .ydrec's first lap is not the MCAP's end";
    }
  }
  const std::size_t compared = std::min(clouds.size() - skipped, laps.size() - first);
  EXPECT_GE(compared + 1 + skipped, clouds.size()) << "the two files stopped more than a lap apart";
  for (std::size_t i = 0; i < compared; ++i)
    EXPECT_TRUE(same_points(clouds[skipped + i], laps[first + i])) << "lap " << i << " differs";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

// The lap indices of a CSV export's rows with the returns of each (the rows whose range_mm is
// not 0: what /points holds).
std::map<std::uint64_t, std::size_t> csv_laps(const std::filesystem::path& path) {
  std::map<std::uint64_t, std::size_t> laps;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header: lap,t,angle_deg,range_mm,flag
  while (std::getline(in, line)) {
    std::size_t& returns = laps[std::stoull(line.substr(0, line.find(',')))];
    std::size_t at = 0;
    for (int comma = 0; comma < 3; ++comma) at = line.find(',', at) + 1;
    returns += std::stod(line.substr(at)) != 0.0 ? 1 : 0;
  }
  return laps;
}

TEST(AppMcap, ExportOfTheShownLapsHoldsEveryFrozenLap) {
  if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const PrivateDisplay display;
  ASSERT_TRUE(display) << "could not start an Xvfb of the test's own";
  X11Hands hands;
  ASSERT_TRUE(hands) << "cannot open the X display";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-app-export-mcap");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  std::set<std::string> seen;
  // Live: M writes once laps are on screen.
  const auto live = new_file(dir, ".mcap", seen, std::chrono::seconds(40), [&] { hands.tap(XK_m, 1); });
  ASSERT_FALSE(live.empty()) << "M wrote no MCAP from the live view";
  EXPECT_GE(clouds_in(read_mcap(file_bytes(live))).size(), 1u);
  std::this_thread::sleep_for(std::chrono::seconds(2));  // the persistence's 10 laps fill

  hands.tap(XK_p, 1);  // freeze
  const auto frozen = new_file(dir, ".mcap", seen, std::chrono::seconds(15), [&] { hands.tap(XK_m, 1); });
  const auto csv = new_file(dir, ".csv", seen, std::chrono::seconds(15), [&] { hands.tap(XK_e, 1); });
  ASSERT_FALSE(frozen.empty());
  ASSERT_FALSE(csv.empty());
  const auto shown = csv_laps(csv);
  ASSERT_EQ(shown.size(), 10u) << "the default persistence shows 10 laps";
  const McapContents contents = read_mcap(file_bytes(frozen));
  ASSERT_TRUE(contents.complete);
  EXPECT_EQ(contents.stat_messages, 2 * shown.size() + 1)
      << "one /scan and one /points per shown lap, and the lidar's /tf_static";
  const auto clouds = clouds_in(contents);
  ASSERT_EQ(clouds.size(), shown.size());
  std::size_t i = 0;
  for (const auto& [lap, returns] : shown) EXPECT_EQ(clouds[i++].size(), returns) << "lap " << lap;
  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
