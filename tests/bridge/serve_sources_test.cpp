// ydscope-cli serve with two --port, as a robot runs it: each lidar's topics under its name, the
// poses on /tf_static, and each lidar's laps flowing to a Foxglove client that subscribes.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "support/ws_test_client.h"
#include "core/sim/sim_server.h"
#include "support/temp_dir.h"

extern char** environ;

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ServeSources, EachLidarUnderItsNameAndEveryPoseOnTfStatic) {
  const test::TempDir temp("serve-sources");
  const fs::path& dir = temp.path();
  std::vector<std::unique_ptr<SimServer>> sims;
  for (const auto& [model, link] : {std::pair{Model::G1, "g1"}, std::pair{Model::G6, "g6"}}) {
    SimServerOptions options;
    options.device.model = model;
    options.device.scene = "room";
    options.transport = SimTransport::Pty;
    options.pty_link = (dir / link).string();
    sims.push_back(std::make_unique<SimServer>(options));
    sims.back()->start();
  }
  std::vector<std::string> text{
      YDSCOPE_CLI_PATH, "serve",           "--port",   (dir / "g1").string(), "--name",    "front",
      "--pose",         "0.2,0,0",         "--port",   (dir / "g6").string(), "--name",    "back",
      "--pose",         "-0.2,0,180,flip", "--listen", "127.0.0.1:0",         "--seconds", "30"};
  std::vector<char*> argv;
  for (auto& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, (dir / "out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, (dir / "err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  ASSERT_EQ(::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  // "serving ws://127.0.0.1:PORT for 2 lidars: ..." (bounded wait: a hang guard).
  std::string out;
  for (int i = 0; i < 200 && out.find('\n') == std::string::npos; ++i) {
    std::this_thread::sleep_for(50ms);
    out = slurp(dir / "out");
  }
  const std::size_t colon = out.find("127.0.0.1:");
  ASSERT_NE(colon, std::string::npos) << out << slurp(dir / "err");
  const auto port = static_cast<std::uint16_t>(std::stoul(out.substr(colon + 10)));
  EXPECT_NE(out.find("for 2 lidars: front on "), std::string::npos) << out;

  {
    test::WsTestClient client(port);
    const std::map<std::uint32_t, std::string> subscriptions = {
        {1, "/front/scan"}, {2, "/back/points"}, {3, "/tf_static"}, {4, "/back/diagnostics"}};
    for (const auto& [id, topic] : subscriptions) ASSERT_TRUE(client.subscribe(id, topic)) << topic;
    std::map<std::uint32_t, std::size_t> received;
    for (int i = 0; i < 400 && (received[1] < 3 || received[2] < 3 || received[3] < 1 || received[4] < 1); ++i) {
      const auto message = client.read_binary(5s);
      if (!message) break;
      ++received[message->subscription];
      EXPECT_GT(message->payload_bytes, 0u);
    }
    EXPECT_GE(received[1], 3u) << "front's /scan";
    EXPECT_GE(received[2], 3u) << "back's /points";
    EXPECT_GE(received[3], 1u) << "/tf_static";
    EXPECT_GE(received[4], 1u) << "back's /diagnostics";
  }
  {
    // No un-namespaced topics with several lidars (a timed-out look closes this client).
    test::WsTestClient client(port);
    EXPECT_NE(client.channel_of("/front/points"), 0u);
    EXPECT_EQ(client.channel_of("/scan", 1s), 0u);
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << slurp(dir / "err");
  sims.clear();
}

}  // namespace
}  // namespace ydscope
