// PortDiscovery over a fake /dev and /sys tree shaped like the kernel's: by-id links, ttyUSB
// (usb-serial: port -> interface -> device) and ttyACM (interface -> device) layouts.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/link/port_discovery.h"
#include "support/session_test_support.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;

class FakeSystem : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dev());
    fs::create_directories(sys());
  }

  fs::path dev() const { return root_ / "dev"; }
  fs::path sys() const { return root_ / "sys"; }

  void node(const std::string& name) { std::ofstream(dev() / name).put('\0'); }
  static void attribute(const fs::path& file, const std::string& value) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << value << "\n";
  }
  // A USB device folder with its identity attributes.
  fs::path usb_device(const std::string& bus_path, const std::string& vid, const std::string& pid,
                      const std::string& manufacturer, const std::string& product, const std::string& serial) {
    const fs::path dir = sys() / "devices" / "pci0000:00" / "0000:00:14.0" / "usb1" / bus_path;
    attribute(dir / "idVendor", vid);
    attribute(dir / "idProduct", pid);
    if (!manufacturer.empty()) attribute(dir / "manufacturer", manufacturer);
    if (!product.empty()) attribute(dir / "product", product);
    if (!serial.empty()) attribute(dir / "serial", serial);
    return dir;
  }
  // /sys/class/tty/<name>/device -> target (relative link, as the kernel makes them).
  void class_tty(const std::string& name, const fs::path& target, const std::string& driver) {
    const fs::path dir = sys() / "class" / "tty" / name;
    fs::create_directories(dir);
    fs::create_directories(target);
    fs::create_symlink(fs::relative(target, dir), dir / "device");
    if (!driver.empty()) fs::create_symlink("../../../../bus/usb-serial/drivers/" + driver, target / "driver");
  }
  void by_id(const std::string& link_name, const std::string& target) {
    fs::create_directories(dev() / "serial" / "by-id");
    fs::create_symlink(target, dev() / "serial" / "by-id" / link_name);
  }

  test::TempDir root_{"ports"};
};

TEST_F(FakeSystem, ListsUsbSerialPortsWithTheirIdentityKnownBridgesFirst) {
  for (const char* name : {"ttyUSB0", "ttyUSB1", "ttyUSB10", "ttyACM0", "ttyS0", "ttyUSBx", "tty1", "null"}) node(name);
  const fs::path cp2102 =
      usb_device("1-1", "10c4", "ea60", "Silicon Labs", "CP2102 USB to UART Bridge Controller", "0001");
  class_tty("ttyUSB1", cp2102 / "1-1:1.0" / "ttyUSB1", "cp210x");
  const fs::path ch340 = usb_device("1-3", "1a86", "7523", "", "USB Serial", "");
  class_tty("ttyUSB0", ch340 / "1-3:1.0" / "ttyUSB0", "ch341-uart");
  const fs::path arduino = usb_device("1-2", "2341", "0043", "Arduino (www.arduino.cc)", "Uno", "7573");
  class_tty("ttyACM0", arduino / "1-2:1.0", "");
  by_id("usb-Silicon_Labs_CP2102_USB_to_UART_Bridge_Controller_0001-if00-port0", "../../ttyUSB1");
  by_id("usb-gone-if00-port0", "../../ttyUSB7");  // dangling: unplugged a moment ago

  const auto ports = PortDiscovery(dev().string(), sys().string()).list();
  ASSERT_EQ(ports.size(), 4u);
  EXPECT_EQ(ports[0].name, "ttyUSB0");
  EXPECT_EQ(ports[1].name, "ttyUSB1");
  EXPECT_EQ(ports[2].name, "ttyACM0");
  EXPECT_EQ(ports[3].name, "ttyUSB10");

  EXPECT_TRUE(ports[0].known_lidar_bridge);
  EXPECT_EQ(ports[0].usb_id(), "1a86:7523");
  EXPECT_EQ(ports[0].driver, "ch341-uart");
  EXPECT_EQ(ports[0].preferred_path(), (dev() / "ttyUSB0").string());

  const auto& cp = ports[1];
  EXPECT_TRUE(cp.known_lidar_bridge);
  EXPECT_EQ(cp.path, (dev() / "ttyUSB1").string());
  EXPECT_EQ(
      cp.by_id,
      (dev() / "serial" / "by-id" / "usb-Silicon_Labs_CP2102_USB_to_UART_Bridge_Controller_0001-if00-port0").string());
  EXPECT_EQ(cp.preferred_path(), cp.by_id);
  EXPECT_EQ(cp.vendor_id, 0x10c4);
  EXPECT_EQ(cp.product_id, 0xea60);
  EXPECT_EQ(cp.manufacturer, "Silicon Labs");
  EXPECT_EQ(cp.product, "CP2102 USB to UART Bridge Controller");
  EXPECT_EQ(cp.serial, "0001");
  EXPECT_EQ(cp.driver, "cp210x");
  EXPECT_EQ(cp.description(), "Silicon Labs CP2102 USB to UART Bridge Controller (10c4:ea60)");

  EXPECT_FALSE(ports[2].known_lidar_bridge);
  EXPECT_EQ(ports[2].usb_id(), "2341:0043");  // ttyACM: identity one level up from the interface
  EXPECT_EQ(ports[2].serial, "7573");

  EXPECT_FALSE(ports[3].vendor_id);  // no sysfs entry
  EXPECT_EQ(ports[3].description(), "");

  const auto first = first_lidar_candidate(ports);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->name, "ttyUSB0");
}

TEST_F(FakeSystem, ByIdLinkAloneStillNamesThePort) {
  by_id("usb-WCH_USB_Serial-if00-port0", "../../ttyUSB3");
  node("ttyUSB3");
  const auto ports = PortDiscovery(dev().string(), sys().string()).list();
  ASSERT_EQ(ports.size(), 1u);
  EXPECT_EQ(ports[0].name, "ttyUSB3");
  EXPECT_EQ(ports[0].by_id, (dev() / "serial/by-id/usb-WCH_USB_Serial-if00-port0").string());
}

TEST_F(FakeSystem, UdevAliasJoinsItsPort) {
  node("ttyUSB0");
  node("ttyUSB1");
  fs::create_symlink("ttyUSB1", dev() / "ydlidar");
  const auto ports = PortDiscovery(dev().string(), sys().string()).list();
  ASSERT_EQ(ports.size(), 2u);
  EXPECT_TRUE(ports[0].alias.empty());
  EXPECT_EQ(ports[1].alias, (dev() / "ydlidar").string());
  EXPECT_EQ(ports[1].preferred_path(), (dev() / "ydlidar").string());
  by_id("usb-Silicon_Labs_CP2102-if00-port0", "../../ttyUSB1");
  EXPECT_EQ(PortDiscovery(dev().string(), sys().string()).list()[1].preferred_path(),
            (dev() / "serial/by-id/usb-Silicon_Labs_CP2102-if00-port0").string());
}

TEST_F(FakeSystem, PerBridgeUdevNamesJoinTheirPorts) {
  node("ttyUSB0");
  node("ttyUSB1");
  fs::create_symlink("ttyUSB1", dev() / "ydlidar-0001");
  fs::create_symlink("ttyUSB0", dev() / "ydlidar-pci-0000_00_14_0-usb-0_2_1_0");
  fs::create_symlink("ttyUSB7", dev() / "ydlidar-gone");  // dangling: that bridge was unplugged
  const auto ports = PortDiscovery(dev().string(), sys().string()).list();
  ASSERT_EQ(ports.size(), 2u);
  EXPECT_EQ(ports[0].alias, (dev() / "ydlidar-pci-0000_00_14_0-usb-0_2_1_0").string());
  EXPECT_EQ(ports[1].alias, (dev() / "ydlidar-0001").string());
  EXPECT_EQ(ports[1].preferred_path(), (dev() / "ydlidar-0001").string());
}

TEST_F(FakeSystem, OnBoardUartsComeLastAndAreNeverTheAutomaticChoice) {
  // A Pi's PL011, a Jetson's UART, an 8250 port with a 16550A behind it (type 4), and the three
  // placeholders the 8250 driver makes anyway (type 0, or no sysfs entry at all).
  for (const char* name : {"ttyAMA0", "ttyTHS1", "ttyS0", "ttyS1", "ttyS2", "ttyS3", "ttyUSB0"}) node(name);
  attribute(sys() / "class" / "tty" / "ttyS0" / "type", "4");
  attribute(sys() / "class" / "tty" / "ttyS1" / "type", "0");
  attribute(sys() / "class" / "tty" / "ttyS2" / "type", "");
  const auto ports = PortDiscovery(dev().string(), sys().string()).list();
  ASSERT_EQ(ports.size(), 4u);
  EXPECT_EQ(ports[0].name, "ttyUSB0");
  EXPECT_FALSE(ports[0].on_board_uart);
  EXPECT_EQ(ports[1].name, "ttyAMA0");
  EXPECT_EQ(ports[2].name, "ttyS0");
  EXPECT_EQ(ports[3].name, "ttyTHS1");
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_TRUE(ports[i].on_board_uart) << ports[i].name;
    EXPECT_EQ(ports[i].description(), "on-board UART") << ports[i].name;
  }
  EXPECT_EQ(first_lidar_candidate(ports)->name, "ttyUSB0");
  EXPECT_FALSE(first_lidar_candidate({ports[1], ports[2]})) << "only --port opens an on-board UART";
}

TEST_F(FakeSystem, NoPortsAndMissingFoldersAreJustEmpty) {
  EXPECT_TRUE(PortDiscovery(dev().string(), sys().string()).list().empty());
  EXPECT_TRUE(PortDiscovery((root_ / "nope").string(), (root_ / "nosys").string()).list().empty());
  EXPECT_FALSE(first_lidar_candidate({}));
}

// Runs the CLI and returns its standard output and exit status.
std::pair<std::string, int> run_cli(const std::string& arguments) {
  const std::string command = std::string(YDSCOPE_CLI_PATH) + " " + arguments + " 2>/dev/null";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> chunk{};
  std::size_t got = 0;
  while ((got = std::fread(chunk.data(), 1, chunk.size(), pipe)) > 0) out.append(chunk.data(), got);
  const int status = ::pclose(pipe);
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

TEST_F(FakeSystem, CliListsPortsAsTableAndJson) {
  node("ttyUSB0");
  const fs::path cp2102 = usb_device("1-1", "10c4", "ea60", "Silicon Labs", "CP2102 \"Bridge\"", "0001");
  class_tty("ttyUSB0", cp2102 / "1-1:1.0" / "ttyUSB0", "cp210x");
  const std::string roots = "--dev-root " + dev().string() + " --sys-root " + sys().string();

  const auto [table, table_status] = run_cli("ports " + roots);
  EXPECT_EQ(table_status, 0);
  EXPECT_NE(table.find("PORT"), std::string::npos) << table;
  EXPECT_NE(table.find((dev() / "ttyUSB0").string() + "  likely   10c4:ea60"), std::string::npos) << table;

  const auto [json, json_status] = run_cli("ports --format json " + roots);
  EXPECT_EQ(json_status, 0);
  EXPECT_EQ(json,
            "[\n  {\"path\":\"" + (dev() / "ttyUSB0").string() +
                "\",\"by_id\":null,\"alias\":null,\"name\":\"ttyUSB0\",\"vendor_id\":\"10c4\",\"product_id\":\"ea60\","
                "\"manufacturer\":\"Silicon Labs\",\"product\":\"CP2102 \\\"Bridge\\\"\",\"serial\":\"0001\","
                "\"driver\":\"cp210x\",\"known_lidar_bridge\":true,\"on_board_uart\":false}\n]\n");

  EXPECT_EQ(run_cli("ports --format json --dev-root " + (root_ / "none").string()).first, "[]\n");
  EXPECT_EQ(run_cli("ports --format xml").second, 2);
}

// --ask: the lidar on each likely port says its own serial (A5 90), beside the USB bridge's; a
// likely port with no lidar behind it says so; without --ask no port is opened (the JSON above).
TEST_F(FakeSystem, AskAddsTheSerialEachLidarAnswersWith) {
  test::SimOnPty sim(Model::G6, [](SimServerOptions& o) { o.device.serial = "0123456789ABCDEF"; });
  fs::create_symlink(sim.port(), dev() / "ttyUSB0");
  class_tty("ttyUSB0", usb_device("1-1", "10c4", "ea60", "Silicon Labs", "CP2102", "0001") / "1-1:1.0" / "ttyUSB0",
            "cp210x");
  node("ttyUSB1");  // a CH340 with nothing that answers behind it
  class_tty("ttyUSB1", usb_device("1-3", "1a86", "7523", "", "USB Serial", "") / "1-3:1.0" / "ttyUSB1", "ch341-uart");
  const std::string roots = "--dev-root " + dev().string() + " --sys-root " + sys().string();

  const auto [table, table_status] = run_cli("ports --ask " + roots);
  EXPECT_EQ(table_status, 0);
  EXPECT_NE(table.find("serial 0001, driver cp210x; lidar serial 0123456789ABCDEF"), std::string::npos) << table;
  EXPECT_NE(table.find("driver ch341-uart; no lidar answered"), std::string::npos) << table;

  const auto [json, json_status] = run_cli("ports --ask --format json " + roots);
  EXPECT_EQ(json_status, 0);
  EXPECT_NE(json.find(R"("serial":"0001","driver":"cp210x","known_lidar_bridge":true,"on_board_uart":false,)"
                      R"("unit_serial":"0123456789ABCDEF"})"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find(R"("on_board_uart":false,"unit_serial":null})"), std::string::npos) << json;
}

TEST_F(FakeSystem, CliJsonIsValidUtf8WhateverTheDeviceSays) {
  node("ttyUSB0");
  // A cheap bridge's manufacturer string: Latin-1 bytes, a cut-off UTF-8 sequence, a control byte.
  const fs::path bridge = usb_device("1-2", "1a86", "7523", "Caf\xe9 \xc3", "ok \xc3\xa9\x01",
                                     "\xff"
                                     "1");
  class_tty("ttyUSB0", bridge / "1-2:1.0" / "ttyUSB0", "ch341");
  const auto [json, status] =
      run_cli("ports --format json --dev-root " + dev().string() + " --sys-root " + sys().string());
  EXPECT_EQ(status, 0);
  EXPECT_NE(json.find(R"("manufacturer":"Caf\ufffd \ufffd")"), std::string::npos) << json;
  EXPECT_NE(json.find("\"product\":\"ok \xc3\xa9\\u0001\""), std::string::npos) << json;  // valid UTF-8 kept
  EXPECT_NE(json.find(R"("serial":"\ufffd1")"), std::string::npos) << json;
}

TEST(LidarBridges, KnownChips) {
  EXPECT_TRUE(is_known_lidar_bridge(0x10c4, 0xea60));
  EXPECT_TRUE(is_known_lidar_bridge(0x1a86, 0x7523));
  EXPECT_FALSE(is_known_lidar_bridge(0x0403, 0x6001));  // FTDI: could be anything
}

}  // namespace
}  // namespace ydscope
