// --port parsing: device paths, tcp://host:port (IPv4, names, bracketed IPv6) and the errors.
#include <gtest/gtest.h>

#include "core/link/link_address.h"
#include "link/await_support.h"

namespace ydscope {
namespace {

TEST(LinkAddress, DevicePathIsSerial) {
  std::string error;
  const auto address = parse_link_address("/dev/serial/by-id/usb-Silicon_Labs_CP2102-if00-port0", error);
  ASSERT_TRUE(address) << error;
  EXPECT_EQ(address->kind, LinkAddress::Kind::Serial);
  EXPECT_EQ(address->path, "/dev/serial/by-id/usb-Silicon_Labs_CP2102-if00-port0");
  EXPECT_EQ(address->text(), address->path);
}

TEST(LinkAddress, TcpHostAndPort) {
  std::string error;
  auto address = parse_link_address("tcp://192.168.1.20:2000", error);
  ASSERT_TRUE(address) << error;
  EXPECT_EQ(address->kind, LinkAddress::Kind::Tcp);
  EXPECT_EQ(address->host, "192.168.1.20");
  EXPECT_EQ(address->port, 2000);
  EXPECT_EQ(address->text(), "tcp://192.168.1.20:2000");

  address = parse_link_address("tcp://lidar-bridge.local:65535", error);
  ASSERT_TRUE(address) << error;
  EXPECT_EQ(address->host, "lidar-bridge.local");
  EXPECT_EQ(address->port, 65535);
}

TEST(LinkAddress, BracketedIpv6) {
  std::string error;
  const auto address = parse_link_address("tcp://[::1]:4001", error);
  ASSERT_TRUE(address) << error;
  EXPECT_EQ(address->host, "::1");
  EXPECT_EQ(address->port, 4001);
  EXPECT_EQ(address->text(), "tcp://[::1]:4001");
}

struct BadAddress {
  const char* text;
  const char* expected_fragment;
};

TEST(LinkAddress, ErrorsNameTheProblem) {
  const BadAddress cases[] = {
      {"", "no port given"},
      {"tcp://", "missing ':port'"},
      {"tcp://host", "missing ':port'"},
      {"tcp://:2000", "missing host"},
      {"tcp://host:", "from 1 to 65535"},
      {"tcp://host:0", "from 1 to 65535"},
      {"tcp://host:65536", "from 1 to 65535"},
      {"tcp://host:20x0", "from 1 to 65535"},
      {"tcp://host:-1", "from 1 to 65535"},
      {"tcp://::1:2000", "brackets"},
      {"tcp://[::1", "missing ']'"},
      {"tcp://[::1]2000", "missing ':port'"},
      {"tcp://[[a]:1", "cannot hold another '['"},  // issue 17: was host "[a", printed as tcp://[a:1
      {"tcp://[a[b]:1", "cannot hold another '['"},
      {"tcp://a]:1", "brackets go around a whole IPv6 host"},
      {"tcp://[a]]:1", "missing ':port'"},
      {"udp://host:2000", "unknown scheme 'udp'"},
  };
  for (const auto& bad : cases) {
    std::string error;
    EXPECT_FALSE(parse_link_address(bad.text, error)) << bad.text;
    EXPECT_NE(error.find(bad.expected_fragment), std::string::npos) << bad.text << " -> " << error;
  }
}

TEST(LinkAddress, FactoryReportsParseAndOpenErrors) {
  boost::asio::io_context io;
  std::string error;
  EXPECT_FALSE(test::run_awaitable(io, open_byte_link(io, "tcp://host", 230400, error)));
  EXPECT_NE(error.find("missing ':port'"), std::string::npos) << error;
  EXPECT_FALSE(test::run_awaitable(io, open_byte_link(io, "/dev/ttyDOESNOTEXIST9", 230400, error)));
  EXPECT_NE(error.find("no such device"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
