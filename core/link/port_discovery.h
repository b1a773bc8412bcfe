#pragma once
// Lists the serial ports a lidar may be on: /dev/serial/by-id/* (stable names), /dev/ydlidar-*
// (made by assets/70-ydlidar.rules; /dev/ydlidar by older versions of it), /dev/ttyUSB*, /dev/ttyACM*,
// and single-board computers' on-board UARTs (ttyAMA*, ttyTHS*, ttyS* with a UART behind it), with
// the USB identity sysfs knows (vendor/product id, manufacturer, product,
// serial, driver). The roots are parameters so tests can point it at a fake /dev and /sys.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ydscope {

struct SerialPortInfo {
  std::string path;   // device node, e.g. /dev/ttyUSB0
  std::string by_id;  // stable /dev/serial/by-id/... name pointing at it, if any
  std::string alias;  // /dev/ydlidar-SERIAL (or the older /dev/ydlidar) when the udev rule points it here
  std::string name;   // ttyUSB0
  std::optional<std::uint16_t> vendor_id;
  std::optional<std::uint16_t> product_id;
  std::string manufacturer;
  std::string product;
  std::string serial;
  std::string driver;               // kernel driver: cp210x, ch341, cdc_acm, ...
  bool known_lidar_bridge = false;  // a USB-serial chip YDLIDAR adapter boards use
  bool on_board_uart = false;       // ttyAMA*, ttyTHS*, or a ttyS* with a UART behind it

  // The name to open: the by-id name survives re-plugging into another USB socket and, unlike
  // /dev/ydlidar, tells two lidars apart.
  const std::string& preferred_path() const { return !by_id.empty() ? by_id : !alias.empty() ? alias : path; }
  // "10c4:ea60" or "" when not a USB device.
  std::string usb_id() const;
  // "Silicon Labs CP2102 USB to UART Bridge Controller (10c4:ea60)" or "" when nothing is known.
  std::string description() const;
};

// CP210x (10c4:ea60) and CH340/CH9102 (1a86:7523, 1a86:55d4): the bridges on YDLIDAR boards.
bool is_known_lidar_bridge(std::uint16_t vendor_id, std::uint16_t product_id);

class PortDiscovery {
 public:
  explicit PortDiscovery(std::string dev_root = "/dev", std::string sys_root = "/sys");

  // Every candidate once (a by-id link and its ttyUSB node are one port), known lidar bridges
  // first, then by name (ttyACM0, ttyUSB0, ttyUSB1, ttyUSB10). Missing folders mean no ports.
  std::vector<SerialPortInfo> list() const;

 private:
  void fill_from_sysfs(SerialPortInfo& port) const;
  bool has_real_uart(const std::string& name) const;

  std::string dev_root_;
  std::string sys_root_;
};

// The port to try when none was given: the first of list() (known bridges come first) that is
// not an on-board UART (those are listed, but only --port opens them), or empty.
std::optional<SerialPortInfo> first_lidar_candidate(const std::vector<SerialPortInfo>& ports);

}  // namespace ydscope
