// The fault matrix: every fault the virtual lidar can inject, against `ydscope-cli scan` and
// `ydscope-cli record` run as a user would, with the lidar on a pseudo-terminal. Each run must end
// (no hang: a bound, not a time assertion), by itself and not by a signal, with the exit status
// and the sentence the fault calls for, and every lap the fault did not touch must come out: the
// device's own record of what it sent (and what a fault kept off the line or broke) is compared
// with the laps scan printed, or decode read back from the recording.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_run_support.h"
#include "core/record/recording_reader.h"
#include "cli/fault_matrix_support.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

using namespace test;
namespace fs = std::filesystem;

// What happens to the link during the run, on a condition (laps or bytes seen), not on a timer.
enum class LinkEvent { None, Unplug, UnplugReplug, LongStall };

struct FaultCase {
  const char* name;
  Model model;
  std::function<void(SimServerOptions&)> inject;
  LinkEvent event = LinkEvent::None;
  int exit_status = 0;
  const char* sentence = "";  // must appear on stderr ("": no error or warning at all)
};

std::vector<FaultCase> fault_cases() {
  return {
      {"none", Model::G6, [](SimServerOptions&) {}},
      {"corrupt", Model::G6, [](SimServerOptions& o) { o.device.faults.corrupt_byte_rate = 2e-4; }},
      {"corrupt_g1", Model::G1, [](SimServerOptions& o) { o.device.faults.corrupt_byte_rate = 2e-4; }},
      {"drop", Model::G6, [](SimServerOptions& o) { o.device.faults.drop_byte_rate = 5e-5; }},
      {"lose_packets", Model::TG30, [](SimServerOptions& o) { o.device.faults.lost_packet_rate = 0.02; }},
      {"lose_packets_g1", Model::G1, [](SimServerOptions& o) { o.device.faults.lost_packet_rate = 0.02; }},
      {"short_stalls", Model::G6,
       [](SimServerOptions& o) {
         o.device.faults.stall_ms = 300;
         o.device.faults.stall_every_ms = 700;
       }},
      // Laps of a lidar reporting an error come out, and the run exits 3 (it ran, the lidar is not right).
      {"health_bits_g1", Model::G1, [](SimServerOptions& o) { o.device.faults.health_bits = 0x05; }, LinkEvent::None, 3,
       "health error: "},
      {"health_error_g6", Model::G6, [](SimServerOptions& o) { o.device.faults.health_bits = 0x21; }, LinkEvent::None,
       3, "health error: the lidar answered A5 91 with error (error code 0x0021)"},
      {"junk_before_replies", Model::TG15, [](SimServerOptions& o) { o.device.faults.junk_before_reply = 40; }},
      {"health_quirk", Model::G6, [](SimServerOptions& o) { o.device.health_quirk = true; }},
      {"health_quirk_g1", Model::G1, [](SimServerOptions& o) { o.device.health_quirk = true; }},
      {"motor_off_rate", Model::G1,
       [](SimServerOptions& o) {
         o.device.faults.scan_hz_offset = 0.4;
         o.device.faults.scan_hz_wobble = 0.3;
       }},
      {"unplug", Model::G6, [](SimServerOptions&) {}, LinkEvent::Unplug, 1, "unplugged"},
      {"unplug_replug", Model::TG50, [](SimServerOptions&) {}, LinkEvent::UnplugReplug, 1, "unplugged"},
      {"long_stall", Model::G6, [](SimServerOptions&) {}, LinkEvent::LongStall, 1, "no data"},
  };
}

enum class Command { Scan, Record };

struct MatrixParam {
  FaultCase fault;
  Command command;
};

std::string param_name(const ::testing::TestParamInfo<MatrixParam>& info) {
  return std::string(info.param.command == Command::Scan ? "scan_" : "record_") + info.param.fault.name;
}

constexpr std::chrono::milliseconds kRunPatience{60000};

class FaultMatrix : public ::testing::TestWithParam<MatrixParam> {
 protected:
  std::string path(const char* name) const { return dir_.file(name); }

  // Waits (bounded) until `ready`; false when it never became true.
  static bool wait_until(const std::function<bool()>& ready) {
    const auto give_up = std::chrono::steady_clock::now() + kPatience;
    while (!ready()) {
      if (std::chrono::steady_clock::now() > give_up) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
  }

  // Applies the link event once the run has shown what it does when healthy.
  void apply_event(SimOnPty& sim, const std::function<bool()>& healthy_run_seen) {
    const LinkEvent event = GetParam().fault.event;
    if (event == LinkEvent::None) return;
    ASSERT_TRUE(wait_until(healthy_run_seen)) << "the run never got going";
    if (event == LinkEvent::LongStall) {
      sim.server().stall(std::chrono::milliseconds(3000));  // longer than the CLI's 2 s stall timeout
      return;
    }
    sim.server().unplug();
    if (event == LinkEvent::UnplugReplug) sim.server().replug();
  }

  test::TempDir dir_{"fault-matrix"};
};

std::size_t lap_lines(const std::string& text) { return printed_laps(text).size(); }

TEST_P(FaultMatrix, EndsWithItsSentenceAndDeliversEveryUntouchedLap) {
  const FaultCase& fault = GetParam().fault;
  const bool scan = GetParam().command == Command::Scan;
  // Declared before the sim so it outlives the sim's thread, which calls it until the sim stops.
  TruthRecorder truth;
  SimOnPty sim(fault.model, [&](SimServerOptions& o) {
    o.device.seed = 7;
    fault.inject(o);
  });
  sim.server().with_device([&](VirtualLidar& d) { d.set_truth([&](const TruthPacket& p) { truth.add(p); }); });

  const bool event = fault.event != LinkEvent::None;
  std::vector<std::string> args;
  if (scan)
    args = {"scan", "--port", sim.port(), "--laps", event ? "100000" : "8"};
  else
    args = {"record", "--port", sim.port(), "--out", path("run.ydrec"), "--seconds", event ? "60" : "1"};
  // A link event ends the run only when asked to; riding it out is RideOutALinkFault's.
  if (event) args.push_back("--no-reconnect");
  CliProcess cli(args, path("stdout"), path("stderr"));
  ASSERT_TRUE(cli.started());
  apply_event(sim, [&] {
    if (scan) return lap_lines(slurp(path("stdout"))) >= 2;
    // Three laps of scan bytes in the file (a G6 lap is about 2.7 kB), flushed as it records.
    std::string error;
    const auto summary = fs::exists(path("run.ydrec")) ? summarize_recording(path("run.ydrec"), error) : std::nullopt;
    return summary && summary->device_bytes >= 12000;
  });
  const int status = cli.wait(kRunPatience);
  const std::string err = cli.err();
  ASSERT_NE(status, -1) << "ydscope-cli hung; stderr: " << err;
  ASSERT_LT(status, 128) << "ydscope-cli was ended by signal " << status - 128 << "; stderr: " << err;
  EXPECT_EQ(status, fault.exit_status) << err;
  if (*fault.sentence) {
    EXPECT_NE(err.find(fault.sentence), std::string::npos) << err;
    EXPECT_LE(std::count(err.begin(), err.end(), '\n'), 2) << "one sentence, not a trace: " << err;
  } else {
    EXPECT_EQ(err.find("error"), std::string::npos) << err;
    EXPECT_EQ(err.find("warning"), std::string::npos) << err;
  }

  std::string laps_text = cli.out();
  if (!scan) {  // what the recording holds, as the user would read it back
    const CliResult decoded = run_cli_apart("decode '" + path("run.ydrec") + "'");
    ASSERT_EQ(decoded.status, 0) << decoded.err;
    laps_text = decoded.out;
  }
  const auto printed = printed_laps(laps_text);
  if (scan && !event) {
    EXPECT_EQ(printed.size(), 8u);
  }
  ASSERT_GE(printed.size(), event ? 2u : 4u) << laps_text.substr(0, 300);
  const SimCounters counters = sim.counters();
  const LapMatch match = match_laps(truth.laps(), printed);
  // A dropped byte is the one fault the device's truth does not mark: it can cost the lap it
  // falls in and, through the resync, the next.
  const std::size_t drop_allowance = 2 * counters.faults.dropped_bytes;
  EXPECT_LE(match.untouched_missing, drop_allowance)
      << match.untouched_missing << " of " << match.untouched << " untouched laps did not come out (" << match.touched
      << " touched, " << match.printed << " printed)";
  EXPECT_GE(match.untouched, 1u) << "the fault touched every lap: make it rarer";
  // A printed lap the device never sent whole is a lap a fault touched.
  EXPECT_LE(match.printed_unknown, match.touched + drop_allowance) << laps_text.substr(0, 300);
}

std::vector<MatrixParam> matrix() {
  std::vector<MatrixParam> params;
  for (const FaultCase& fault : fault_cases())
    for (const Command command : {Command::Scan, Command::Record}) params.push_back({fault, command});
  return params;
}

INSTANTIATE_TEST_SUITE_P(EveryFault, FaultMatrix, ::testing::ValuesIn(matrix()), param_name);

// Issue 26: a single-lidar scan or record ended on any link drop, even with the unit back a
// second later. By default they now reconnect, say the loss and the return, and go on; a
// recording marks the gap in the file.
class RideOutALinkFault : public ::testing::TestWithParam<Command> {
 protected:
  test::TempDir dir_{"ride-out"};
};

TEST_P(RideOutALinkFault, APulledAndReturnedCableCostsOnlyTheGap) {
  const bool scan = GetParam() == Command::Scan;
  SimOnPty sim(Model::G6);
  const std::string out = dir_.file("out"), err_path = dir_.file("err"), recording = dir_.file("run.ydrec");
  std::vector<std::string> args;
  if (scan)
    args = {"scan", "--port", sim.port(), "--laps", "40"};
  else
    args = {"record", "--port", sim.port(), "--out", recording, "--seconds", "6"};
  CliProcess cli(args, out, err_path);
  ASSERT_TRUE(cli.started());
  const auto give_up = std::chrono::steady_clock::now() + kPatience;
  const auto going = [&] {
    if (scan) return lap_lines(slurp(out)) >= 3;
    std::string error;
    const auto summary = fs::exists(recording) ? summarize_recording(recording, error) : std::nullopt;
    return summary && summary->device_bytes >= 12000;
  };
  while (!going() && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(going()) << "the run never got going: " << slurp(err_path);
  sim.server().unplug();
  // Back once the loss was seen: a cable returned within one look of the session can pass unseen.
  const auto lost_said = [&] { return slurp(err_path).find(" stopped: ") != std::string::npos; };
  const auto said_by = std::chrono::steady_clock::now() + kPatience;
  while (!lost_said() && std::chrono::steady_clock::now() < said_by)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  sim.server().replug();

  const int status = cli.wait(kRunPatience);
  const std::string err = cli.err();
  ASSERT_NE(status, -1) << "ydscope-cli hung; stderr: " << err;
  EXPECT_EQ(status, 0) << err;
  EXPECT_NE(err.find(" stopped: "), std::string::npos) << "the loss was not said: " << err;
  EXPECT_NE(err.find(" is scanning again after "), std::string::npos) << "the return was not said: " << err;
  if (scan) {
    EXPECT_EQ(lap_lines(cli.out()), 40u) << "laps did not go on after the return";
    return;
  }
  const CliResult decoded = run_cli_apart("decode '" + recording + "'");
  ASSERT_EQ(decoded.status, 0) << decoded.err;
  EXPECT_GE(lap_lines(decoded.out), 10u);
  // The gap is marked in the file: a link_fault metadata record when the link went, an empty one
  // when it came back.
  const std::string bytes = slurp(recording);
  EXPECT_NE(bytes.find("link_fault=reconnecting to " + sim.port()), std::string::npos)
      << "the file does not mark the gap";
}

INSTANTIATE_TEST_SUITE_P(Commands, RideOutALinkFault, ::testing::Values(Command::Scan, Command::Record),
                         [](const auto& command) {
                           return std::string(command.param == Command::Scan ? "scan" : "record");
                         });

}  // namespace
}  // namespace ydscope
