// Issue 26: input too short for a lap was reported like bytes of another model. decode and replay
// say on stderr why no lap came: not the model's packets, or packets too short for a lap.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_run_support.h"
#include "core/protocol_test_support.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using test::Bytes;

TEST(NoLapCli, PacketsTooShortForALapAreSaidToBeSo) {
  test::TempDir dir("no-lap-cli");
  Bytes short_g6 = test::packet(kCtLapStart, 0.0, 0.0, {0});  // a zero packet, then part of a turn
  test::append(short_g6, test::packet(0, 10.0, 40.0, std::vector<std::uint16_t>(10, 4000)));
  test::append(short_g6, test::packet(0, 50.0, 80.0, std::vector<std::uint16_t>(10, 4000)));
  const std::string raw = dir.file("short.bin");
  test::write_file_bytes(raw, short_g6);
  test::RawRecording recording;  // model G6
  recording.add(RecordType::DeviceToHost, 1'000'000, short_g6);
  const std::string recorded = dir.file("short.ydrec");
  recording.write(recorded);
  const std::string too_short = "no complete lap: its 3 G6 scan packets (" + std::to_string(short_g6.size()) +
                                " bytes) are too short for a lap, which runs from a zero packet to the next zero "
                                "packet; they hold 1 zero packet\n";
  for (const std::string& command :
       {"decode --model G6 '" + raw + "'", "decode '" + recorded + "'", "replay --speed 0 '" + recorded + "'"}) {
    const auto run = test::run_cli_apart(command + " --format summary");
    EXPECT_EQ(run.status, 0) << command << ": " << run.err;
    EXPECT_NE(run.out.find(R"("laps":0)"), std::string::npos) << run.out;
    EXPECT_EQ(run.err, "ydscope-cli " + command.substr(0, command.find(' ')) + ": " + too_short) << command;
  }
  test::write_file_bytes(raw, Bytes(300, 0x5A));
  EXPECT_EQ(test::run_cli_apart("decode --model G6 --format summary '" + raw + "'").err,
            "ydscope-cli decode: no complete lap: its bytes are not G6 scan packets\n");
  // A lap, and nothing is said.
  test::write_file_bytes(raw, test::synthetic_stream(2, 10, 8));
  EXPECT_EQ(test::run_cli_apart("decode --model G6 --format summary '" + raw + "'").err, "");
}

}  // namespace
}  // namespace ydscope
