// ydscope-cli ports: the serial ports a lidar may be on, with their USB identity.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "core/link/port_discovery.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kHelpText = R"(usage: ydscope-cli ports [--format table|json]

Lists the serial ports a lidar may be on: /dev/serial/by-id/* (names that survive re-plugging),
/dev/ydlidar-* (made by the udev rule 70-ydlidar.rules), /dev/ttyUSB* and /dev/ttyACM*, with the
USB vendor:product id, manufacturer, product, serial number and driver that the system reports.
Ports on the USB-serial chips YDLIDAR boards use (CP210x 10c4:ea60, CH340 1a86:7523, CH9102
1a86:55d4) come first and are marked "likely". A single-board computer's own UARTs come last,
marked "uart": /dev/ttyAMA* (Raspberry Pi), /dev/ttyTHS* (Jetson), and /dev/ttyS* where the
kernel found a UART behind it; the app never opens those on its own, give them with --port.
Pass the PORT column to --port of the other commands.

  --format table   (default) one port per line for people.
  --format json    one JSON array of objects: path, by_id, alias, name, vendor_id, product_id (hex text
                   or null), manufacturer, product, serial, driver, known_lidar_bridge, on_board_uart.
  --dev-root DIR, --sys-root DIR
                   look in DIR instead of /dev and /sys (for tests).

A network bridge (ser2net) is not listed: use --port tcp://host:port.

exit status: 0 listed (an empty list too); 2 usage error.

examples:
  ydscope-cli ports
  ydscope-cli ports --format json
)";

void print_table(const std::vector<SerialPortInfo>& ports) {
  if (ports.empty()) {
    std::fputs(
        "no serial ports found (looked for /dev/serial/by-id/*, /dev/ttyUSB*, /dev/ttyACM* and on-board "
        "UARTs /dev/ttyAMA*, /dev/ttyTHS*, /dev/ttyS*); plug the "
        "lidar in, check 'dmesg' for its driver, or use --port tcp://host:port for a network bridge\n",
        stderr);
    return;
  }
  std::size_t width = 4;
  for (const auto& port : ports) width = std::max(width, port.preferred_path().size());
  std::printf("%-*s  %-7s  %-9s  %-7s  %s\n", static_cast<int>(width), "PORT", "LIDAR?", "USB ID", "DEVICE",
              "DESCRIPTION");
  for (const auto& port : ports) {
    std::string description = port.description();
    if (!port.serial.empty()) description += (description.empty() ? "serial " : ", serial ") + port.serial;
    if (!port.driver.empty()) description += (description.empty() ? "driver " : ", driver ") + port.driver;
    const std::string usb = port.usb_id().empty() ? "-" : port.usb_id();
    std::printf("%-*s  %-7s  %-9s  %-7s  %s\n", static_cast<int>(width), port.preferred_path().c_str(),
                port.known_lidar_bridge ? "likely"
                : port.on_board_uart    ? "uart"
                                        : "-",
                usb.c_str(), port.name.c_str(), description.c_str());
  }
}

void hex_or_null(JsonOut& out, const std::optional<std::uint16_t>& value) {
  if (!value) return out.raw("null");
  char text[8];
  std::snprintf(text, sizeof text, "%04x", *value);
  out.string(text);
}

void print_json(const std::vector<SerialPortInfo>& ports) {
  JsonOut out(stdout);
  out.raw("[");
  for (std::size_t i = 0; i < ports.size(); ++i) {
    const auto& port = ports[i];
    out.raw(i == 0 ? "\n  {\"path\":" : ",\n  {\"path\":");
    out.string(port.path);
    out.raw(",\"by_id\":");
    if (port.by_id.empty())
      out.raw("null");
    else
      out.string(port.by_id);
    out.raw(",\"alias\":");
    if (port.alias.empty())
      out.raw("null");
    else
      out.string(port.alias);
    out.raw(",\"name\":");
    out.string(port.name);
    out.raw(",\"vendor_id\":");
    hex_or_null(out, port.vendor_id);
    out.raw(",\"product_id\":");
    hex_or_null(out, port.product_id);
    out.raw(",\"manufacturer\":");
    out.string(port.manufacturer);
    out.raw(",\"product\":");
    out.string(port.product);
    out.raw(",\"serial\":");
    out.string(port.serial);
    out.raw(",\"driver\":");
    out.string(port.driver);
    out.raw(port.known_lidar_bridge ? ",\"known_lidar_bridge\":true" : ",\"known_lidar_bridge\":false");
    out.raw(port.on_board_uart ? ",\"on_board_uart\":true}" : ",\"on_board_uart\":false}");
  }
  out.raw(ports.empty() ? "]\n" : "\n]\n");
  out.flush();
}

int run_ports(std::span<const std::string> raw) {
  const Arguments args(raw, {"format", "dev-root", "sys-root"}, {});
  const std::string format = args.value("format").value_or("table");
  if (format != "table" && format != "json") throw UsageError("--format must be table or json, not '" + format + "'");
  const PortDiscovery discovery(args.value("dev-root").value_or("/dev"), args.value("sys-root").value_or("/sys"));
  const auto ports = discovery.list();
  if (format == "json")
    print_json(ports);
  else
    print_table(ports);
  return kExitOk;
}

const RegisterCliCommand registration{
    {"ports", "list serial ports a lidar may be on, with their USB identity", kHelpText, &run_ports}};

}  // namespace
}  // namespace ydscope::cli
