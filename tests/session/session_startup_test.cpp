// Start-up against the virtual lidar on a pseudo-terminal: model auto-detection for every model,
// baud probing, and the clear failure of a device that never answers.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <thread>

#include "core/link/serial_link.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

class StartupEveryModel : public ::testing::TestWithParam<Model> {};

TEST_P(StartupEveryModel, DetectsTheModelAndReadsItsSettings) {
  const ModelProfile& profile = profile_for(GetParam());
  SimOnPty sim(GetParam());
  Session session;
  session.connect(config_for(sim.port(), std::nullopt, /*scan=*/false));
  const SessionSnapshot s = wait_for_state(session, LinkState::Ready);
  ASSERT_EQ(s.state, LinkState::Ready) << describe_snapshot(s);
  ASSERT_TRUE(s.device.has_value());
  EXPECT_EQ(s.device->profile, &profile);
  EXPECT_EQ(s.device->model_code, profile.model_code);
  EXPECT_FALSE(s.device->serial.empty());
  ASSERT_TRUE(s.health.has_value()) << s.message;
  EXPECT_EQ(s.health->summary, "ok");
  EXPECT_EQ(s.health->command, profile.health_command);
  std::uint32_t sim_centihz = 0;
  std::uint16_t sim_khz = 0;
  double sim_scale = 0;
  sim.server().with_device([&](VirtualLidar& d) {
    sim_centihz = d.scan_centihz();
    sim_khz = d.ranging_khz();
    sim_scale = d.distance_scale();
  });
  ASSERT_TRUE(s.scan_hz.has_value());
  EXPECT_DOUBLE_EQ(*s.scan_hz, sim_centihz / 100.0);
  ASSERT_TRUE(s.ranging_khz.has_value());
  EXPECT_EQ(*s.ranging_khz, sim_khz);
  // The unit is read as real units of its model and firmware write (the virtual one imitates them).
  EXPECT_DOUBLE_EQ(s.distance_scale, sim_scale);
  ASSERT_NE(s.conventions, nullptr);
  EXPECT_EQ(s.conventions->reading, Reading::Field);
  EXPECT_EQ(sim.counters().device.ignored_during_scan, 0u);
}

TEST_P(StartupEveryModel, StartsScanningAndLapsArrive) {
  SimOnPty sim(GetParam());
  Session session;
  session.connect(config_for(sim.port()));
  const SessionSnapshot s = wait_for_state(session, LinkState::Scanning);
  ASSERT_EQ(s.state, LinkState::Scanning) << describe_snapshot(s);
  EXPECT_EQ(take_laps(session, 3), 3u);
  EXPECT_EQ(session.snapshot().counters.checksum_errors, 0u);
  EXPECT_EQ(sim.counters().device.ignored_during_scan, 0u);
}

INSTANTIATE_TEST_SUITE_P(AllModels, StartupEveryModel,
                         ::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30, Model::TG50),
                         [](const auto& param_info) { return std::string(profile_for(param_info.param).name); });

// A serial link that garbles every byte it reads unless the line is at the device's baud,
// as a real UART does at the wrong rate (the pseudo-terminal itself ignores the rate).
class WrongBaudGarbler final : public ByteLink {
 public:
  WrongBaudGarbler(std::unique_ptr<ByteLink> inner, std::uint32_t baud, std::uint32_t device_baud,
                   std::vector<std::uint32_t>& tried)
      : inner_(std::move(inner)), baud_(baud), device_baud_(device_baud), tried_(tried) {
    tried_.push_back(baud);
  }
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    inner_->async_read_some(buffer, [this, buffer, handler](const boost::system::error_code& ec, std::size_t n) {
      if (baud_ != device_baud_)
        for (std::size_t i = 0; i < n; ++i) buffer[i] = static_cast<std::uint8_t>(buffer[i] ^ 0x3C);
      handler(ec, n);
    });
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    if (baud_ == device_baud_) {
      inner_->async_write(bytes, std::move(handler));
    } else {  // the device hears noise: send nothing it could take for a command
      static const std::uint8_t noise[2] = {0x00, 0x00};
      inner_->async_write(std::span<const std::uint8_t>(noise, bytes.size() < 2 ? bytes.size() : 2),
                          std::move(handler));
    }
  }
  void close() override { inner_->close(); }
  bool set_baud(std::uint32_t baud, std::string& error) override {
    if (!inner_->set_baud(baud, error)) return false;
    baud_ = baud;
    tried_.push_back(baud);
    return true;
  }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<ByteLink> inner_;
  std::uint32_t baud_;
  std::uint32_t device_baud_;
  std::vector<std::uint32_t>& tried_;
};

TEST(SessionStartup, ProbesBaudsUntilTheDeviceAnswers) {
  SimOnPty sim(Model::TG30);
  std::vector<std::uint32_t> tried;  // written on the I/O thread, read after the session is gone
  {
    Session session;
    SessionConfig config = config_for(sim.port(), std::nullopt, false);
    config.probe_baud = true;
    config.reply_timeout = 300ms;
    config.command_attempts = 1;
    const std::string port = sim.port();
    config.open_link = [port, &tried](boost::asio::io_context& io, std::uint32_t baud,
                                      std::string& error) -> std::unique_ptr<ByteLink> {
      auto serial = SerialLink::open(io, port, baud, error);
      if (!serial) return nullptr;
      return std::make_unique<WrongBaudGarbler>(std::move(serial), baud, 512000, tried);
    };
    session.connect(config);
    const SessionSnapshot s = wait_for_state(session, LinkState::Ready);
    ASSERT_EQ(s.state, LinkState::Ready) << describe_snapshot(s);
    EXPECT_EQ(s.baud, 512000u);
    ASSERT_TRUE(s.device.has_value());
    EXPECT_EQ(s.device->profile->model, Model::TG30);
  }
  ASSERT_GE(tried.size(), 2u);
  EXPECT_EQ(tried[0], 230400u);
  EXPECT_EQ(tried[1], 512000u);
}

TEST(SessionStartup, ASilentDeviceFailsWithASentence) {
  // A pseudo-terminal with nothing behind it: bytes go out, nothing ever comes back.
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  const std::string slave = ptsname(master);
  Session session;
  SessionConfig config = config_for(slave, Model::G6);
  config.reconnect = false;
  config.reply_timeout = 200ms;
  session.connect(config);
  const SessionSnapshot s = wait_for_state(session, LinkState::Failed);
  close(master);
  ASSERT_EQ(s.state, LinkState::Failed) << describe_snapshot(s);
  EXPECT_NE(s.message.find("no reply to A5 90"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find(slave), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("512000"), std::string::npos) << s.message;
}

TEST(SessionStartup, AMissingPortFailsWithASentence) {
  Session session;
  SessionConfig config = config_for("/dev/ydscope-no-such-port", Model::G1);
  config.reconnect = false;
  session.connect(config);
  const SessionSnapshot s = wait_for_state(session, LinkState::Failed);
  ASSERT_EQ(s.state, LinkState::Failed);
  EXPECT_NE(s.message.find("/dev/ydscope-no-such-port"), std::string::npos) << s.message;
}

// A regular file given as the port: even with reconnecting on (the app, serve), the session says
// once what is wrong and stops, rather than "retrying when ... comes back" for ever.
TEST(SessionStartup, ARegularFileAsThePortFailsOnceEvenWhenReconnecting) {
  char path[] = "/tmp/ydscope-notaport-XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  ::close(fd);
  Session session;
  SessionConfig config = config_for(path, Model::G6);
  ASSERT_TRUE(config.reconnect);
  session.connect(config);
  const SessionSnapshot s = wait_for_state(session, LinkState::Failed, std::chrono::seconds(5));
  ::unlink(path);
  ASSERT_EQ(s.state, LinkState::Failed) << s.message;
  EXPECT_NE(s.message.find("not a serial port"), std::string::npos) << s.message;
  EXPECT_EQ(s.message.find("retrying"), std::string::npos) << s.message;
}

// A program that ends without disconnecting (SIGTERM in serve, a closed window, an exception
// unwinding) destroys its session: the lidar is stopped first, not left spinning.
TEST(SessionStartup, ASessionEndedWhileScanningStopsTheLidar) {
  SimOnPty sim(Model::G6);
  {
    Session session;
    session.connect(config_for(sim.port(), Model::G6));
    ASSERT_EQ(take_laps(session, 2), 2u);
  }
  DeviceMode mode = DeviceMode::Scanning;
  for (int i = 0; i < 100 && mode != DeviceMode::Idle; ++i) {  // the virtual lidar reads it on its thread
    sim.server().with_device([&](VirtualLidar& d) { mode = d.mode(); });
    if (mode != DeviceMode::Idle) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(mode, DeviceMode::Idle) << "the session went without sending A5 65";
}

}  // namespace
}  // namespace ydscope
