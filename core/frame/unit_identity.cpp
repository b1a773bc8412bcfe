#include "core/frame/unit_identity.h"

#include <map>

namespace ydscope {
namespace {

constexpr std::size_t kFree = static_cast<std::size_t>(-1);

std::string with_serial(const std::string& name, const std::string& serial) {
  return name + " (serial " + serial + ")";
}

}  // namespace

UnitIdentity identify_units(const std::vector<SourceInfo>& given, const std::vector<UnitSeen>& seen) {
  const std::size_t n = given.size();
  UnitIdentity out;
  std::map<std::string, std::size_t> ports_per_serial;
  for (std::size_t i = 0; i < n && i < seen.size(); ++i)
    if (!seen[i].serial.empty()) ++ports_per_serial[seen[i].serial];
  for (const auto& [serial, count] : ports_per_serial)
    if (count > 1)
      out.notes.push_back(std::to_string(count) + " units answer with serial " + serial +
                          ", so they cannot be told apart by it; each keeps the name given for its port");
  const auto read_on = [&](std::size_t port) { return port < seen.size() ? seen[port].serial : std::string(); };

  // First the units bound by serial, wherever they are; then each other port keeps its own
  // source if it is free; the rest take what is left, in order.
  std::vector<std::size_t> source_at(n, kFree);
  std::vector<bool> taken(n, false), matched(n, false);
  for (std::size_t port = 0; port < n; ++port) {
    const std::string serial = read_on(port);
    if (serial.empty() || ports_per_serial[serial] > 1) continue;
    for (std::size_t id = 0; id < n; ++id)
      if (!taken[id] && given[id].serial == serial) {
        source_at[port] = id;
        taken[id] = matched[port] = true;
        break;
      }
  }
  for (std::size_t port = 0; port < n; ++port)
    if (source_at[port] == kFree && !taken[port]) source_at[port] = port, taken[port] = true;
  for (std::size_t port = 0, next = 0; port < n; ++port) {
    if (source_at[port] != kFree) continue;
    while (taken[next]) ++next;
    source_at[port] = next;
    taken[next] = true;
  }

  for (std::size_t port = 0; port < n; ++port) {
    const std::size_t id = source_at[port];
    const SourceInfo& source = given[id];
    const std::string serial = read_on(port);
    const std::string& here = seen.size() > port ? seen[port].port : std::string();
    const std::string was = seen.size() > id ? seen[id].port : std::string();
    SourceInfo found = source;
    found.model = given[port].model;  // the decoder belongs to the port's session
    found.serial = serial;
    out.sources.push_back(std::move(found));
    out.moved = out.moved || id != port;
    if (matched[port]) {
      if (id == port) continue;
      const bool swapped = matched[id] && source_at[id] == port;
      if (swapped && port < id)
        out.notes.push_back(with_serial(source.name, serial) + " and " + with_serial(given[port].name, read_on(id)) +
                            " have swapped ports: " + source.name + " is on " + here + ", " + given[port].name +
                            " on " + was + "; each keeps its name and pose");
      else if (!swapped)
        out.notes.push_back(with_serial(source.name, serial) + " is on " + here + " now, not " + was +
                            "; it keeps its name and pose");
    } else if (!source.serial.empty()) {
      out.notes.push_back(source.name + " is bound to serial " + source.serial +
                          ", which no port's unit has; the unit on " + here +
                          (serial.empty() ? ", which did not say its serial," : " (serial " + serial + ")") +
                          " is taken as " + source.name);
    } else if (id != port) {
      out.notes.push_back(source.name + " is on " + here + " now: its port " + was + " holds " +
                          given[source_at[id]].name + "'s unit");
    }
  }
  return out;
}

}  // namespace ydscope
