// Identity by serial end to end: two virtual lidars with different serials on two pseudo-terminals,
// bound by serial, then swapped across the ports. Each keeps its name and pose in the recording
// (its source entry names the port it is now on and carries its serial), and the swap is said in
// one sentence. Bindings come from --serial or from settings.ini's `unit = SERIAL; NAME` lines.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_run_support.h"
#include "core/record/recording_reader.h"
#include "support/program_run.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

constexpr const char* kFrontSerial = "1111222233334444";
constexpr const char* kRearSerial = "5555666677778888";
const Pose kFrontPose{0.3, 0.0, 0.0, false};
const Pose kRearPose{-0.4, 0.1, 180.0, false};

class IdentityCli : public ::testing::Test {
 protected:
  // A virtual lidar of `serial` on the fixed port `link` (a pseudo-terminal behind it).
  std::unique_ptr<test::SimOnPty> unit_on(const std::string& link, const char* serial) {
    return std::make_unique<test::SimOnPty>(Model::G6, [&](SimServerOptions& o) {
      o.pty_link = link;
      o.device.serial = serial;
    });
  }
  std::string port(const char* name) const { return dir_.file(name); }

  struct Source {
    std::string name, port, serial;
    std::optional<Pose> pose;
  };
  // Each source of the recording as written: name, pose and port from its entry, serial as read.
  std::vector<Source> sources_of(const std::string& file) {
    std::string error;
    auto reader = RecordingReader::open(file, error);
    EXPECT_TRUE(reader) << error;
    const auto summary = summarize_recording(file, error);
    EXPECT_TRUE(summary) << error;
    std::vector<Source> out;
    if (!reader || !summary) return out;
    for (std::size_t id = 0; id < reader->source_count(); ++id) {
      const RecordingMetadata& entry = reader->source_metadata(id);
      out.push_back({entry.name.value_or(""), entry.port.value_or(""),
                     summary->sources.at(id).metadata.serial.value_or(""), entry.pose});
    }
    return out;
  }

  test::TempDir dir_{"identity"};
  test::TempDir config_{"identity-config"};
};

TEST_F(IdentityCli, TwoUnitsSwappedAcrossPortsKeepTheirNamesAndPosesAndTheSwapIsSaid) {
  test::RunOptions options;
  options.config_home = config_.string();
  const std::string a = port("usb0"), b = port("usb1");
  const std::string command = "record --port '" + a + "' --name front --serial " + kFrontSerial + " --pose " +
                              format_pose(kFrontPose) + " --port '" + b + "' --name rear --serial " + kRearSerial +
                              " --pose " + format_pose(kRearPose) + " --seconds 0.3 --out ";
  {
    const auto front = unit_on(a, kFrontSerial);
    const auto rear = unit_on(b, kRearSerial);
    const auto run = test::run_program(YDSCOPE_CLI_PATH, command + "'" + dir_.file("as-given.ydrec") + "'", options);
    ASSERT_EQ(run.status, 0) << run.out << run.err;
    EXPECT_EQ(run.err.find("swapped"), std::string::npos) << run.err;
    const auto sources = sources_of(dir_.file("as-given.ydrec"));
    ASSERT_EQ(sources.size(), 2u);
    EXPECT_EQ(sources[0].name, "front");
    EXPECT_EQ(sources[0].serial, kFrontSerial);
  }
  // The cables swapped: front's unit now answers on b, rear's on a.
  const auto rear = unit_on(a, kRearSerial);
  const auto front = unit_on(b, kFrontSerial);
  const std::string mcap = dir_.file("swapped.mcap");
  const auto run = test::run_program(
      YDSCOPE_CLI_PATH, command + "'" + dir_.file("swapped.ydrec") + "' --mcap '" + mcap + "' --compression none",
      options);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(
      run.err.find("ydscope-cli: rear (serial " + std::string(kRearSerial) + ") and front (serial " + kFrontSerial +
                   ") have swapped ports: rear is on " + a + ", front on " + b + "; each keeps its name and pose\n"),
      std::string::npos)
      << run.err;
  const auto sources = sources_of(dir_.file("swapped.ydrec"));
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0].port, a);
  EXPECT_EQ(sources[0].name, "rear");
  EXPECT_EQ(sources[0].pose, kRearPose);
  EXPECT_EQ(sources[0].serial, kRearSerial);
  EXPECT_EQ(sources[1].port, b);
  EXPECT_EQ(sources[1].name, "front");
  EXPECT_EQ(sources[1].pose, kFrontPose);
  EXPECT_EQ(sources[1].serial, kFrontSerial);
  // The MCAP file's /diagnostics carry each unit's serial (uncompressed, so its text is there).
  std::ifstream mcap_file(mcap, std::ios::binary);
  const std::string mcap_bytes(std::istreambuf_iterator<char>(mcap_file), {});
  EXPECT_NE(mcap_bytes.find(kFrontSerial), std::string::npos);
  EXPECT_NE(mcap_bytes.find(kRearSerial), std::string::npos);
  // The summary names each lidar by the name that followed it.
  EXPECT_NE(run.out.find("  rear: G6 on " + a), std::string::npos) << run.out;
}

TEST_F(IdentityCli, SettingsBindNamesToSerialsWhenTheCommandLineGivesNone) {
  {
    std::filesystem::create_directories(config_.path() / "ydscope");
    std::ofstream settings(config_.path() / "ydscope" / "settings.ini");
    settings << "pose_convention = rep103\n"
             << "source = front; 0.3,0,0; #FF8800\nsource = rear; -0.4,0.1,180; #00CCFF\n"
             << "unit = " << kFrontSerial << "; front\nunit = " << kRearSerial << "; rear\n";
  }
  test::RunOptions options;
  options.config_home = config_.string();
  const std::string a = port("usb0"), b = port("usb1");
  const auto rear = unit_on(a, kRearSerial);
  const auto front = unit_on(b, kFrontSerial);
  const std::string out = dir_.file("bound.ydrec");
  const auto run = test::run_program(
      YDSCOPE_CLI_PATH,
      "record --port '" + a + "' --name front --port '" + b + "' --name rear --seconds 0.3 --out '" + out + "'",
      options);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(run.err.find("have swapped ports"), std::string::npos) << run.err;
  const auto sources = sources_of(out);
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0].name, "rear");
  EXPECT_EQ(sources[0].serial, kRearSerial);
  EXPECT_EQ(sources[1].name, "front");
}

TEST_F(IdentityCli, ABadSerialIsOneUsageSentence) {
  const auto run = test::run_cli_apart(
      "record --port /dev/null --name a --serial 'x y' --port /dev/zero --name b "
      "--serial 2 --out '" +
      dir_.file("x.ydrec") + "'");
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("--serial 'x y' must be the unit's serial"), std::string::npos) << run.err;
  const auto lone = test::run_cli_apart("record --port /dev/null --serial 1 --out '" + dir_.file("x.ydrec") + "'");
  EXPECT_EQ(lone.status, 2) << lone.err;
  EXPECT_NE(lone.err.find("--serial binds the name of one of several lidars"), std::string::npos) << lone.err;
  const auto sim = test::run_cli_apart("sim --model G6 --pty '" + dir_.file("l") + "' --serial 12");
  EXPECT_EQ(sim.status, 2) << sim.err;
  EXPECT_NE(sim.err.find("--serial needs 16 characters 0-9 or A-F"), std::string::npos) << sim.err;
}

}  // namespace
}  // namespace ydscope
