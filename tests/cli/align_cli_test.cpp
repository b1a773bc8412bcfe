// ydscope-cli align end to end: two virtual lidars on pseudo-terminals in the room scene, one at
// its origin and one standing at a known pose; align, started 25 degrees and 0.4 m off, finds that
// pose through the whole path (bytes, decoder, laps), prints it as --pose and as a source list,
// and with --apply keeps it where the app looks a lidar's pose up by name.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_run_support.h"
#include "core/frame/pose.h"
#include "support/program_run.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

// The pose printed after "NAME: --pose ", or nothing.
std::optional<Pose> printed_pose(const std::string& out, const std::string& name) {
  const std::string key = name + ": --pose ";
  const std::size_t at = out.find(key);
  if (at == std::string::npos) return std::nullopt;
  const std::size_t from = at + key.size();
  std::string error;
  return parse_pose(out.substr(from, out.find(' ', from) - from), error);
}

TEST(AlignCli, FindsAVirtualLidarsPoseOverPseudoTerminalsAndAppliesIt) {
  const Pose truth{0.6, -0.4, 35.0, false};
  test::SimOnPty reference(Model::G6);
  test::SimOnPty other(Model::TG30, [&](SimServerOptions& o) { o.device.pose = truth; });
  test::TempDir config{"align-config"};
  test::RunOptions options;
  options.config_home = config.string();
  const std::string ports = "--port '" + reference.port() + "' --name front --port '" + other.port() + "' --name rear";

  const auto run = test::run_program(YDSCOPE_CLI_PATH,
                                     "align " + ports + " --pose 0,0,0 --pose 0.2,-0.6,10 --laps 6 --apply", options);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  const auto found = printed_pose(run.out, "rear");
  ASSERT_TRUE(found) << run.out;
  EXPECT_LT(1000.0 * std::hypot(found->x_m - truth.x_m, found->y_m - truth.y_m), 20.0) << run.out;
  EXPECT_LT(std::abs(std::remainder(found->yaw_deg - truth.yaw_deg, 360.0)), 0.5) << run.out;
  EXPECT_NE(run.out.find("residual "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("source list: --port " + reference.port() + " --name front --pose 0,0,0 --port " +
                         other.port() + " --name rear --pose " + format_pose(*found)),
            std::string::npos)
      << run.out;

  // --apply: the app's settings.ini remembers rear's pose by its name.
  std::ifstream file(config / "ydscope" / "settings.ini");
  const std::string settings(std::istreambuf_iterator<char>(file), {});
  EXPECT_NE(settings.find("source = rear; " + format_pose(*found) + "; #"), std::string::npos) << settings;

  // A second run without --pose starts from the remembered poses and finds the same place.
  const auto again = test::run_program(YDSCOPE_CLI_PATH, "align " + ports + " --laps 4", options);
  ASSERT_EQ(again.status, 0) << again.out << again.err;
  const auto refound = printed_pose(again.out, "rear");
  ASSERT_TRUE(refound) << again.out;
  EXPECT_LT(1000.0 * std::hypot(refound->x_m - truth.x_m, refound->y_m - truth.y_m), 20.0) << again.out;
}

TEST(AlignCli, OneLidarIsAUsageError) {
  const auto run = test::run_cli_apart("align --port /dev/null");
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("two or more lidars"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace ydscope
