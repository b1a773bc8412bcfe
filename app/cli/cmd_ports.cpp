// ydscope-cli ports: the serial ports a lidar may be on, with their USB identity.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "app/cli/session_cli.h"
#include "app/cli/units_by_serial.h"
#include "core/link/port_discovery.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kPortsHelp = R"(usage: ydscope-cli ports [--format table|json] [--ask]

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
                   or null), manufacturer, product, serial, driver, known_lidar_bridge, on_board_uart
                   (and unit_serial with --ask).
  --ask            also ask the lidar on each port marked "likely" for its own serial number (A5 90,
                   all at once, a few seconds): the unit's, which follows the lidar, where "serial"
                   is the USB adapter's. A scanning lidar is stopped to answer; a port another program
                   holds, or one with no lidar, gives none. Other ports are not opened.
  --dev-root DIR, --sys-root DIR
                   look in DIR instead of /dev and /sys (for tests).

A network bridge (ser2net) is not listed: use --port tcp://host:port.

exit status: 0 listed (an empty list too); 2 usage error.

examples:
  ydscope-cli ports
  ydscope-cli ports --format json
)";

// Per port, the serial its lidar answered with; empty where it was not asked or did not answer.
using UnitSerials = std::vector<std::optional<std::string>>;

UnitSerials ask_likely_ports(const std::vector<SerialPortInfo>& ports) {
  std::vector<SessionConfig> configs;
  std::vector<std::size_t> asked;
  for (std::size_t i = 0; i < ports.size(); ++i) {
    if (!ports[i].known_lidar_bridge) continue;
    configs.push_back(session_config_for(ports[i].path, std::nullopt, std::nullopt, /*scan=*/false));
    asked.push_back(i);
  }
  UnitSerials serials(ports.size());
  const std::vector<std::string> answered = configs.empty() ? std::vector<std::string>() : ask_serials(configs);
  for (std::size_t k = 0; k < asked.size(); ++k) serials[asked[k]] = answered[k];
  return serials;
}

void print_table(const std::vector<SerialPortInfo>& ports, const UnitSerials& units) {
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
    const auto& unit = units[static_cast<std::size_t>(&port - ports.data())];
    if (unit) description += unit->empty() ? "; no lidar answered" : "; lidar serial " + *unit;
    const std::string usb = port.usb_id().empty() ? "-" : port.usb_id();
    std::printf("%-*s  %-7s  %-9s  %-7s  %s\n", static_cast<int>(width), port.preferred_path().c_str(),
                port.known_lidar_bridge ? "likely"
                : port.on_board_uart    ? "uart"
                                        : "-",
                usb.c_str(), port.name.c_str(), description.c_str());
  }
}

// "10c4": USB ids as lsusb and udev write them.
std::optional<std::string> hex_text(const std::optional<std::uint16_t>& value) {
  if (!value) return std::nullopt;
  char text[8];
  std::snprintf(text, sizeof text, "%04x", *value);
  return text;
}

void print_json(const std::vector<SerialPortInfo>& ports, const UnitSerials& units, bool asked) {
  JsonOut out(stdout);
  {
    JsonArray list(out.buffer(), "  ");
    for (std::size_t i = 0; i < ports.size(); ++i) {
      const SerialPortInfo& port = ports[i];
      JsonObject object = list.object();
      object.field("path", port.path)
          .field("by_id", text_or_null(port.by_id))
          .field("alias", text_or_null(port.alias))
          .field("name", port.name)
          .field("vendor_id", hex_text(port.vendor_id))
          .field("product_id", hex_text(port.product_id))
          .field("manufacturer", port.manufacturer)
          .field("product", port.product)
          .field("serial", port.serial)
          .field("driver", port.driver)
          .field("known_lidar_bridge", port.known_lidar_bridge)
          .field("on_board_uart", port.on_board_uart);
      if (asked) object.field("unit_serial", units[i] && !units[i]->empty() ? units[i] : std::nullopt);
    }
  }
  out.raw("\n");
  out.flush();
}

int run_ports(std::span<const std::string> raw) {
  const Arguments args(raw, {"format", "dev-root", "sys-root"}, {"ask"});
  const std::string format = args.value("format").value_or("table");
  if (format != "table" && format != "json") throw UsageError("--format must be table or json, not '" + format + "'");
  const PortDiscovery discovery(args.value("dev-root").value_or("/dev"), args.value("sys-root").value_or("/sys"));
  const auto ports = discovery.list();
  const bool ask = args.has("ask");
  const UnitSerials units = ask ? ask_likely_ports(ports) : UnitSerials(ports.size());
  if (format == "json")
    print_json(ports, units, ask);
  else
    print_table(ports, units);
  return kExitOk;
}

const RegisterCliCommand ports_command{
    {"ports", "list serial ports a lidar may be on, with their USB identity", kPortsHelp, &run_ports}};

}  // namespace
}  // namespace ydscope::cli
