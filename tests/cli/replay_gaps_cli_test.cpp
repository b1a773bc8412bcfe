// Issue 26: a legal 59 s gap in a recording paused `replay` for 59 s without a word. It is said on
// stderr, with where it is and how long, and skipped unless --keep-gaps asks to wait it out; for
// one lidar and several alike.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_run_support.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using test::RawRecording;

// Under `timeout`: waiting the gap out at speed 1 fails the test instead of stalling it.
class ReplayGapsCli : public ::testing::Test {
 protected:
  // Device bytes at 1 and 2 s, then none for 59 s, then at 61 and 62 s; of `sources` lidars.
  std::string write(const std::string& name, std::uint16_t sources) {
    RawRecording recording(sources > 1 ? 2 : 1, 16, "model=G6\n");
    for (std::uint16_t source = 1; source < sources; ++source)
      recording.add(RecordType::Metadata, 0, {'m', 'o', 'd', 'e', 'l', '=', 'G', '1', '\n'}, source);
    for (const std::int64_t t : std::vector<std::int64_t>{1'000'000'000, 2'000'000'000, 61'000'000'000, 62'000'000'000})
      for (std::uint16_t source = 0; source < sources; ++source)
        recording.add(RecordType::DeviceToHost, t, {0x00, 0x01}, source);
    const std::string file = dir_.file(name);
    recording.write(file);
    return file;
  }
  test::TempDir dir_{"replay-gaps-cli"};
};

TEST_F(ReplayGapsCli, AGapIsSaidAndSkippedOrWaitedOut) {
  const std::string said =
      "ydscope-cli replay: the recording has a gap of 59.0 s at 2.0 s without a byte from the "
      "lidar; ";
  for (const std::uint16_t sources : {std::uint16_t{1}, std::uint16_t{2}}) {
    const std::string file = write("gap" + std::to_string(sources) + ".ydrec", sources);
    // Its bytes are no scan packets: one lidar's replay says so after the gap (no_lap_cli_test.cpp).
    const std::string no_lap =
        sources == 1 ? "ydscope-cli replay: no complete lap: its bytes are not G6 scan packets\n" : "";
    const auto skipped = test::run_cli_bounded("replay --format summary '" + file + "'");
    EXPECT_EQ(skipped.status, 0) << sources << " lidars: " << skipped.err;
    EXPECT_EQ(skipped.err, said + "skipped to 61.0 s (--keep-gaps waits gaps out)\n" + no_lap);
    EXPECT_NE(skipped.out.find(R"("bytes":8)"), std::string::npos) << skipped.out;
    const auto kept = test::run_cli_bounded("replay --format summary --keep-gaps --speed 1000 '" + file + "'");
    EXPECT_EQ(kept.status, 0) << kept.err;
    EXPECT_EQ(kept.err, said + "waiting it out, playing on at 61.0 s (skipped without --keep-gaps)\n" + no_lap);
    EXPECT_EQ(kept.out, skipped.out) << "the same laps and times either way";
  }
  const auto help = test::run_cli_apart("replay --help");
  EXPECT_NE(help.out.find("--keep-gaps"), std::string::npos);
}

}  // namespace
}  // namespace ydscope
