#pragma once
// Waiting for a lidar to be plugged in and pulled out, for `check --loop` at a test station. With
// a port path the wait is on that path (inotify wakes it as soon as the node or link appears,
// core/link/port_watch.h); without one, on the first lidar port discovery lists
// (core/link/port_discovery.h), as `ydscope-cli ports` would show it.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

namespace ydscope::cli {

// The port to open once a unit is there and the port can be opened for reading and writing (udev
// gives a new node its permissions a moment after creating it); empty when `stop` was set first.
// `port`: the path to wait for, or empty to take the first lidar port that appears.
std::optional<std::string> wait_for_unit(const std::string& port, const std::atomic<bool>& stop);

// Which file `path` names (device and inode numbers and change time of the name itself, not
// following a link), empty when it leads nowhere: a unit plugged in again, or another in its
// place, makes a new node (or link) even under the same name.
struct PortNode {
  std::uint64_t device = 0, inode = 0;
  std::int64_t changed_ns = 0;  // a freed inode number may be given to the very next file
  bool operator==(const PortNode&) const = default;
};
std::optional<PortNode> port_node(const std::string& path);

// Returns true once `path` no longer leads to `unit` (the unit was pulled out, or swapped faster
// than a look), false when `stop` was set first.
bool wait_until_unplugged(const std::string& path, const std::optional<PortNode>& unit, const std::atomic<bool>& stop);

}  // namespace ydscope::cli
