// SerialLink against a pseudo-terminal the test opens itself: the same path a USB port takes.
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "core/link/serial_link.h"
#include "core/link/termios2_baud.h"
#include "link/link_read_support.h"

namespace ydscope {
namespace {

// The master side of a pty; its slave path is what the link opens, like /dev/ttyUSB0.
class PseudoTerminal {
 public:
  PseudoTerminal() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
    std::array<char, 128> name{};
    if (::ptsname_r(master_, name.data(), name.size()) == 0) slave_path_ = name.data();
  }
  ~PseudoTerminal() {
    if (master_ >= 0) ::close(master_);
  }
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  int master() const { return master_; }
  const std::string& slave_path() const { return slave_path_; }

  // Reads exactly n bytes from the master, or fewer if nothing arrives for 5 s (a hang guard).
  std::vector<std::uint8_t> read_master(std::size_t n) const {
    std::vector<std::uint8_t> out;
    while (out.size() < n) {
      pollfd pfd{master_, POLLIN, 0};
      if (::poll(&pfd, 1, 5000) <= 0) break;
      std::array<std::uint8_t, 256> chunk{};
      const auto got = ::read(master_, chunk.data(), std::min(chunk.size(), n - out.size()));
      if (got <= 0) break;
      out.insert(out.end(), chunk.begin(), chunk.begin() + got);
    }
    return out;
  }

 private:
  int master_ = -1;
  std::string slave_path_;
};

constexpr auto kSerialHangGuard = std::chrono::seconds(5);

// Opens the pty's slave the way the session opens a port; a failure fails the test with its sentence.
std::unique_ptr<SerialLink> open_slave(boost::asio::io_context& io, const PseudoTerminal& pty, std::uint32_t baud) {
  std::string error;
  auto link = SerialLink::open(io, pty.slave_path(), baud, error);
  EXPECT_TRUE(link) << error;
  return link;
}

TEST(SerialLink, OpensPtyRawAt512000BaudThroughTermios2) {
  PseudoTerminal pty;
  ASSERT_FALSE(pty.slave_path().empty());
  boost::asio::io_context io;
  auto link = open_slave(io, pty, 512000);
  ASSERT_TRUE(link);

  termios2::LineSettings settings;
  ASSERT_EQ(termios2::read_settings(link->native_handle(), settings), 0);
  EXPECT_EQ(settings.output_baud, 512000u);
  EXPECT_EQ(settings.input_baud, 512000u);
  EXPECT_TRUE(settings.arbitrary_baud);
  EXPECT_TRUE(settings.raw);
  EXPECT_TRUE(settings.eight_n_one);
  EXPECT_FALSE(settings.flow_control);

  // Cross-check with the ordinary termios API, independent of our termios2 code.
  termios tio{};
  ASSERT_EQ(::tcgetattr(link->native_handle(), &tio), 0);
  EXPECT_EQ(tio.c_lflag & (ICANON | ECHO | ISIG), 0u);
  EXPECT_EQ(tio.c_oflag & OPOST, 0u);
  EXPECT_EQ(tio.c_iflag & (ICRNL | IXON | IXOFF), 0u);
  EXPECT_EQ(tio.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(tio.c_cflag & (PARENB | CSTOPB | CRTSCTS), 0u);
  EXPECT_EQ(link->describe(), pty.slave_path() + " at 512000 baud");
}

TEST(SerialLink, SetBaudChangesTheRateAndKeepsRawMode) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  std::string error;
  auto link = open_slave(io, pty, 230400);
  ASSERT_TRUE(link);
  ASSERT_TRUE(link->set_baud(512000, error)) << error;
  termios2::LineSettings settings;
  ASSERT_EQ(termios2::read_settings(link->native_handle(), settings), 0);
  EXPECT_EQ(settings.output_baud, 512000u);
  EXPECT_TRUE(settings.raw);
  EXPECT_EQ(link->baud(), 512000u);
  EXPECT_FALSE(link->set_baud(0, error));
}

TEST(SerialLink, CarriesEveryByteValueBothWays) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  auto link = open_slave(io, pty, 230400);
  ASSERT_TRUE(link);

  // All 256 values: raw mode must not translate CR/LF, eat ^C/^S or echo anything.
  std::vector<std::uint8_t> device_bytes(256);
  for (std::size_t i = 0; i < device_bytes.size(); ++i) device_bytes[i] = static_cast<std::uint8_t>(i);
  ASSERT_EQ(::write(pty.master(), device_bytes.data(), device_bytes.size()), static_cast<ssize_t>(device_bytes.size()));

  const auto received = test::read_from_link(io, *link, device_bytes.size(), 64, kSerialHangGuard);
  EXPECT_FALSE(received.end) << received.end.message();
  EXPECT_EQ(received.bytes, device_bytes);

  const std::array<std::uint8_t, 4> commands{0xA5, 0x65, 0xA5, 0x0D};
  bool written = false;
  link->async_write(commands, [&](const boost::system::error_code& ec, std::size_t n) {
    EXPECT_FALSE(ec);
    EXPECT_EQ(n, commands.size());
    written = true;
  });
  io.restart();
  io.run_for(kSerialHangGuard);
  EXPECT_TRUE(written);
  EXPECT_EQ(pty.read_master(commands.size()), std::vector<std::uint8_t>(commands.begin(), commands.end()));
  // No echo: the master saw only the commands, not the 256 bytes it sent.
  pollfd pfd{pty.master(), POLLIN, 0};
  EXPECT_EQ(::poll(&pfd, 1, 0), 0);
}

TEST(SerialLink, CloseAbortsAPendingRead) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  auto link = open_slave(io, pty, 230400);
  ASSERT_TRUE(link);
  std::array<std::uint8_t, 16> buffer{};
  boost::system::error_code seen;
  bool called = false;
  link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t) {
    seen = ec;
    called = true;
  });
  boost::asio::post(io, [&] { link->close(); });
  io.run_for(kSerialHangGuard);
  EXPECT_TRUE(called);
  EXPECT_EQ(seen, boost::asio::error::operation_aborted);
  EXPECT_EQ(link->native_handle(), -1);
}

TEST(SerialLink, InputThatArrivesWhileUnwatchedIsAllReadAfterwards) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  auto link = open_slave(io, pty, 512000);
  ASSERT_TRUE(link);
  link->stop_watching_input();
  std::vector<std::uint8_t> device_bytes(3000);
  for (std::size_t i = 0; i < device_bytes.size(); ++i) device_bytes[i] = static_cast<std::uint8_t>(i * 7);
  for (std::size_t sent = 0; sent < device_bytes.size(); sent += 100)
    ASSERT_EQ(::write(pty.master(), device_bytes.data() + sent, 100), 100);
  // Nothing watches the port, so the context has nothing to do while the bytes pile up.
  EXPECT_EQ(io.poll(), 0u);

  const auto received = test::read_from_link(io, *link, device_bytes.size(), 4096, kSerialHangGuard);
  EXPECT_FALSE(received.end) << received.end.message();
  EXPECT_EQ(received.bytes, device_bytes);
}

TEST(SerialLink, CommandsGoOutWhileInputIsUnwatched) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  auto link = open_slave(io, pty, 512000);
  ASSERT_TRUE(link);
  link->stop_watching_input();
  const std::array<std::uint8_t, 2> stop{0xA5, 0x65};
  bool written = false;
  link->async_write(stop, [&](const boost::system::error_code& ec, std::size_t) { written = !ec; });
  io.run_for(kSerialHangGuard);
  EXPECT_TRUE(written);
  EXPECT_EQ(pty.read_master(stop.size()), std::vector<std::uint8_t>(stop.begin(), stop.end()));
}

TEST(SerialLink, ASecondOpenOfTheSamePortIsToldItIsBusy) {
  PseudoTerminal pty;
  boost::asio::io_context io;
  std::string error;
  auto first = open_slave(io, pty, 512000);
  ASSERT_TRUE(first);
  EXPECT_FALSE(SerialLink::open(io, pty.slave_path(), 512000, error));
  EXPECT_NE(error.find("busy"), std::string::npos) << error;
  first->close();
  EXPECT_TRUE(SerialLink::open(io, pty.slave_path(), 512000, error)) << error;
}

TEST(SerialLink, MissingDeviceIsOneActionableSentence) {
  boost::asio::io_context io;
  std::string error;
  EXPECT_FALSE(SerialLink::open(io, "/dev/ttyDOESNOTEXIST9", 230400, error));
  EXPECT_EQ(error.rfind("cannot open /dev/ttyDOESNOTEXIST9: no such device", 0), 0u) << error;
  EXPECT_NE(error.find("ydscope-cli ports"), std::string::npos) << error;
}

TEST(SerialLink, RegularFileIsNotASerialPort) {
  char path[] = "/tmp/ydscope-notatty-XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  ::close(fd);
  boost::asio::io_context io;
  std::string error;
  EXPECT_FALSE(SerialLink::open(io, path, 230400, error));
  EXPECT_NE(error.find("not a serial port"), std::string::npos) << error;
  ::unlink(path);
}

TEST(SerialLink, OpenErrorSentencesSayWhatToDo) {
  EXPECT_NE(serial_open_error("/dev/ttyUSB0", EACCES).find("dialout"), std::string::npos);
  EXPECT_NE(serial_open_error("/dev/ttyUSB0", EACCES).find("/usr/lib/udev/rules.d/70-ydlidar.rules"),
            std::string::npos);
  EXPECT_EQ(serial_open_error("/tmp", EISDIR),
            "cannot open /tmp: it is a folder, not a serial port; give a device such as /dev/ttyUSB0 "
            "('ydscope-cli ports' lists them)");
  EXPECT_NE(serial_open_error("/dev/ttyUSB0", EBUSY).find("busy"), std::string::npos);
  EXPECT_EQ(serial_open_error("/dev/ttyUSB0", EACCES).rfind("cannot open /dev/ttyUSB0: permission denied", 0), 0u);
}

}  // namespace
}  // namespace ydscope
