#include "core/link/port_discovery.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

namespace ydscope {
namespace {

namespace fs = std::filesystem;

struct Bridge {
  std::uint16_t vendor;
  std::uint16_t product;
};
constexpr std::array<Bridge, 3> kLidarBridges{{
    {0x10c4, 0xea60},  // Silicon Labs CP210x
    {0x1a86, 0x7523},  // WCH CH340
    {0x1a86, 0x55d4},  // WCH CH9102
}};

bool numbered(const std::string& name, const std::string& prefix) {
  return name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
         std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

bool is_usb_serial_name(const std::string& name) { return numbered(name, "ttyUSB") || numbered(name, "ttyACM"); }

// Single-board computers wire lidars to their own UARTs: a Raspberry Pi's PL011 (ttyAMA), a
// Jetson's (ttyTHS), and 8250-style ports (ttyS) on many others.
bool is_on_board_uart_name(const std::string& name) {
  return numbered(name, "ttyAMA") || numbered(name, "ttyTHS") || numbered(name, "ttyS");
}

std::string read_attribute(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

std::optional<std::uint16_t> parse_hex16(const std::string& text) {
  std::uint16_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// "ttyUSB10" sorts after "ttyUSB9": split into prefix and number.
std::tuple<std::string, long> natural_key(const std::string& name) {
  std::size_t digits = name.size();
  while (digits > 0 && name[digits - 1] >= '0' && name[digits - 1] <= '9') --digits;
  long number = -1;
  if (digits < name.size()) std::from_chars(name.data() + digits, name.data() + name.size(), number);
  return {name.substr(0, digits), number};
}

}  // namespace

bool is_known_lidar_bridge(std::uint16_t vendor_id, std::uint16_t product_id) {
  return std::any_of(kLidarBridges.begin(), kLidarBridges.end(),
                     [&](const Bridge& b) { return b.vendor == vendor_id && b.product == product_id; });
}

std::string SerialPortInfo::usb_id() const {
  if (!vendor_id || !product_id) return "";
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "%04x:%04x", *vendor_id, *product_id);
  return text.data();
}

std::string SerialPortInfo::description() const {
  if (on_board_uart && manufacturer.empty() && product.empty()) return "on-board UART";
  std::string text = manufacturer;
  if (!product.empty()) text += (text.empty() ? "" : " ") + product;
  const std::string id = usb_id();
  if (!id.empty()) text += (text.empty() ? "" : " ") + ("(" + id + ")");
  return text;
}

PortDiscovery::PortDiscovery(std::string dev_root, std::string sys_root)
    : dev_root_(std::move(dev_root)), sys_root_(std::move(sys_root)) {}

void PortDiscovery::fill_from_sysfs(SerialPortInfo& port) const {
  std::error_code ec;
  const fs::path device_link = fs::path(sys_root_) / "class" / "tty" / port.name / "device";
  const fs::path device = fs::canonical(device_link, ec);
  if (ec) return;  // not in sysfs (e.g. a pty or a container without /sys)
  if (const fs::path driver = fs::read_symlink(device / "driver", ec); !ec) port.driver = driver.filename().string();
  // ttyUSB: device is the usb-serial port, its parent the interface, then the USB device.
  // ttyACM: device is the interface. Walk up to the first folder that has idVendor.
  const fs::path sys_root = fs::canonical(sys_root_, ec);
  fs::path dir = device;
  for (int level = 0; level < 4 && !dir.empty() && dir != dir.root_path(); ++level, dir = dir.parent_path()) {
    if (!sys_root.empty() && dir.string().rfind(sys_root.string(), 0) != 0) break;
    if (!fs::exists(dir / "idVendor", ec)) continue;
    port.vendor_id = parse_hex16(read_attribute(dir / "idVendor"));
    port.product_id = parse_hex16(read_attribute(dir / "idProduct"));
    port.manufacturer = read_attribute(dir / "manufacturer");
    port.product = read_attribute(dir / "product");
    port.serial = read_attribute(dir / "serial");
    break;
  }
  port.known_lidar_bridge =
      port.vendor_id && port.product_id && is_known_lidar_bridge(*port.vendor_id, *port.product_id);
}

std::vector<SerialPortInfo> PortDiscovery::list() const {
  std::map<std::string, SerialPortInfo> by_name;  // keyed by tty name: one entry per port
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dev_root_, ec)) {
    const std::string name = entry.path().filename().string();
    const bool uart = is_on_board_uart_name(name);
    if (!is_usb_serial_name(name) && !(uart && has_real_uart(name))) continue;
    SerialPortInfo& port = by_name[name];
    port.name = name;
    port.path = entry.path().string();
    port.on_board_uart = uart;
  }
  const fs::path by_id_dir = fs::path(dev_root_) / "serial" / "by-id";
  std::vector<fs::path> links;
  for (const auto& entry : fs::directory_iterator(by_id_dir, ec)) links.push_back(entry.path());
  std::sort(links.begin(), links.end());  // deterministic choice when two names point at one port
  for (const auto& link : links) {
    std::error_code resolve_error;
    const fs::path target = fs::canonical(link, resolve_error);
    if (resolve_error) continue;  // dangling: the device just went away
    const std::string name = target.filename().string();
    SerialPortInfo& port = by_name[name];
    port.name = name;
    if (port.path.empty()) port.path = (fs::path(dev_root_) / name).string();
    if (port.by_id.empty()) port.by_id = link.string();
  }
  // Names the udev rule makes: /dev/ydlidar-SERIAL per bridge, or /dev/ydlidar from older rules.
  std::vector<fs::path> aliases;
  for (const auto& entry : fs::directory_iterator(dev_root_, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == "ydlidar" || name.rfind("ydlidar-", 0) == 0) aliases.push_back(entry.path());
  }
  std::sort(aliases.begin(), aliases.end());
  for (const auto& alias : aliases) {
    std::error_code resolve_error;
    const fs::path target = fs::canonical(alias, resolve_error);
    if (resolve_error) continue;
    const std::string name = target.filename().string();
    if (!is_usb_serial_name(name) && !(is_on_board_uart_name(name) && has_real_uart(name))) continue;
    SerialPortInfo& port = by_name[name];
    port.name = name;
    port.on_board_uart = is_on_board_uart_name(name);
    if (port.path.empty()) port.path = (fs::path(dev_root_) / name).string();
    if (port.alias.empty()) port.alias = alias.string();
  }
  std::vector<SerialPortInfo> ports;
  for (auto& [name, port] : by_name) {
    fill_from_sysfs(port);
    ports.push_back(std::move(port));
  }
  std::sort(ports.begin(), ports.end(), [](const SerialPortInfo& a, const SerialPortInfo& b) {
    if (a.known_lidar_bridge != b.known_lidar_bridge) return a.known_lidar_bridge;
    if (a.on_board_uart != b.on_board_uart) return b.on_board_uart;
    return natural_key(a.name) < natural_key(b.name);
  });
  return ports;
}

std::optional<SerialPortInfo> first_lidar_candidate(const std::vector<SerialPortInfo>& ports) {
  // Not an on-board UART: many PCs have a real ttyS0, and probing it would only delay the demo.
  for (const SerialPortInfo& port : ports)
    if (!port.on_board_uart) return port;
  return std::nullopt;
}

bool PortDiscovery::has_real_uart(const std::string& name) const {
  // ttyAMA and ttyTHS nodes exist only for hardware that is there. The 8250 driver makes ttyS0-3
  // whether or not a UART answers; sysfs's `type` is 0 (PORT_UNKNOWN) for those placeholders.
  if (!numbered(name, "ttyS")) return true;
  const std::string type = read_attribute(fs::path(sys_root_) / "class" / "tty" / name / "type");
  return !type.empty() && type != "0";
}

}  // namespace ydscope
