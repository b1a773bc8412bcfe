// Recording through the session: every byte both ways lands in the file on the I/O thread, with
// the device's metadata, and the recorded device bytes decode into the laps the session saw.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/protocol/scan_decoder.h"
#include "core/record/recording_reader.h"
#include "core/record/recording_writer.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using namespace test;

TEST(SessionRecording, RecordsBothDirectionsAndTheDeviceMetadata) {
  SimOnPty sim(Model::G6);
  const test::TempDir dir("session-recording");
  const std::string path = dir.file("session.ydrec");
  std::uint64_t session_laps = 0;
  {
    Session session(64);
    const CommandResult started = run_command([&](CommandCallback done) { session.start_recording(path, done); });
    ASSERT_TRUE(started.ok) << started.message;
    EXPECT_TRUE(session.snapshot().recording);
    session.connect(config_for(sim.port()));
    ASSERT_EQ(take_laps(session, 4), 4u) << describe_snapshot(session.snapshot());
    const CommandResult set = run_command([&](CommandCallback done) { session.set_scan_hz(10.0, done); });
    ASSERT_TRUE(set.ok) << set.message;
    ASSERT_EQ(take_laps(session, 4), 4u);
    const CommandResult stopped = run_command([&](CommandCallback done) { session.stop_recording(done); });
    ASSERT_TRUE(stopped.ok) << stopped.message;
    EXPECT_FALSE(session.snapshot().recording);
    session_laps = session.snapshot().counters.laps;
  }

  std::string error;
  auto reader = RecordingReader::open(path, error);
  ASSERT_TRUE(reader) << error;
  std::string sent;
  ScanDecoder decoder = test::field_decoder(Model::G6);
  std::uint64_t decoded_laps = 0;
  RecordView record;
  while (reader->next(record)) {
    if (record.type == RecordType::HostToDevice) {
      for (const auto byte : record.payload) sent += static_cast<char>(byte);
    } else if (record.type == RecordType::DeviceToHost) {
      decoder.feed(record.payload, record.t_ns, [&](const Lap&) { ++decoded_laps; });
    }
  }
  EXPECT_FALSE(reader->corrupt()) << reader->error();
  const RecordingMetadata& metadata = reader->metadata();
  EXPECT_EQ(metadata.model, "G6");
  EXPECT_EQ(metadata.model_code, 13u);
  EXPECT_TRUE(metadata.serial.has_value());
  EXPECT_EQ(metadata.port, sim.port());
  // Start-up asked stop, device info, health, scan Hz, ranging, then scanned; the set stopped first.
  for (const std::string command : {"\xA5\x65", "\xA5\x90", "\xA5\x91", "\xA5\x0D", "\xA5\xD1", "\xA5\x60", "\xA5\x0B"})
    EXPECT_NE(sent.find(command), std::string::npos)
        << "command byte " << static_cast<int>(static_cast<std::uint8_t>(command[1]));
  // The recording's device bytes hold every lap the session decoded (a lap cut by a command's
  // stop is one the session discards too, so the counts can differ by those).
  EXPECT_GE(decoded_laps + 2, session_laps);
  EXPECT_GE(decoded_laps, 8u);
}

// The app records through the session: a device or a folder is refused at once, with the
// sentence the CLI gives, instead of a file that cannot be read back.
TEST(SessionRecording, RefusesAnOutputThatIsNotARegularFile) {
  Session session(4);
  for (const std::string& path : {std::string("/dev/null"), std::filesystem::temp_directory_path().string()}) {
    const CommandResult started = run_command([&](CommandCallback done) { session.start_recording(path, done); });
    EXPECT_FALSE(started.ok) << path;
    EXPECT_EQ(started.message, recording_output_problem(path));
    EXPECT_NE(started.message.find("cannot record to " + path + ": it is "), std::string::npos) << started.message;
    EXPECT_FALSE(session.snapshot().recording);
  }
}

}  // namespace
}  // namespace ydscope
