#pragma once
// SimServer: a VirtualLidar served from one background thread on a pseudo-terminal (the host opens
// the slave path like any serial port) or on a TCP port (like a ser2net bridge), one host at a time.
// Used in-process by tests and by the app (`ydscope --sim G6`), and by `ydscope-cli sim`.
//
// The thread waits in ppoll on the port and a wake-up eventfd with a timeout set to the device's
// next due bytes, so it never spins. Bytes the device sends while no host has the port open are
// lost, as on a real line, and counted. Every public method is thread-safe.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "core/sim/delivery.h"
#include "core/sim/faults.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope {

enum class SimTransport : std::uint8_t { Pty, Tcp };

struct SimServerOptions {
  VirtualLidarConfig device;
  SimTransport transport = SimTransport::Pty;
  // Pty: optional symlink made to point at the slave path (kept pointing at it across replugs,
  // removed on stop). Must not exist, or be a dangling symlink into /dev/pts left by an earlier run.
  std::string pty_link;
  // Tcp: listen address (loopback by default); port 0 picks a free port (see SimServer::tcp_port).
  std::string tcp_host = "127.0.0.1";
  std::uint16_t tcp_port = 0;
  // How the bytes reach the host (core/sim/delivery.h); Whole is the line as it carries them.
  DeliveryModel delivery;
  // Called on the server thread with CLOCK_MONOTONIC ns just after the write() that carried a zero
  // packet's last byte returned; zero_index counts zero packets since the server started.
  std::function<void(std::int64_t mono_ns, std::uint64_t zero_index)> on_zero_packet_written;
  // Same, appended to this file as lines "<zero_index> <mono_ns>" (flushed each line). Empty = off.
  std::string zero_packet_log;
  // Commands received, mode changes, plug events (called on the server thread). Empty = quiet.
  std::function<void(std::string_view line)> on_log;
  // Scheduled disconnect fault, relative to start(): unplug after this long, then replug after
  // replug_after (zero: stay unplugged). Zero unplug_after = off.
  std::chrono::milliseconds unplug_after{0};
  std::chrono::milliseconds replug_after{0};
  // The device runs this many times faster than real time (its line too: a pseudo-terminal has
  // no baud), for soak benchmarks; 1 = real time. Stall and unplug times are in device time.
  double time_scale = 1.0;
};

struct SimServerCounters {
  std::uint64_t bytes_in = 0;       // host bytes handed to the device
  std::uint64_t bytes_written = 0;  // device bytes a host could read
  // Device bytes lost because no host had the port open, or because the host read too slowly and
  // the port's buffer was full (a UART overruns the same way).
  std::uint64_t bytes_unheard = 0;
  std::uint64_t host_connections = 0;  // TCP accepts, or pty opens noticed
  std::uint64_t rejected_hosts = 0;    // TCP hosts turned away because one was already connected
  std::uint64_t unplugs = 0;
  std::uint64_t replugs = 0;
  std::uint64_t zero_packets_written = 0;
  // Laps that lost bytes so: lap i runs from the i-th zero packet written whole to the next one.
  std::uint64_t laps_overrun = 0;
};

struct SimCounters {
  DeviceCounters device;
  FaultCounters faults;
  SimServerCounters server;
};

class SimServer {
 public:
  explicit SimServer(SimServerOptions options);
  ~SimServer();  // stop()
  SimServer(const SimServer&) = delete;
  SimServer& operator=(const SimServer&) = delete;

  // Opens the port and starts the thread. Throws std::runtime_error with one sentence saying what
  // failed (link path taken, port in use, no pseudo-terminals...).
  void start();
  // Stops the thread, closes the port, removes the symlink. Idempotent.
  void stop();
  bool running() const;

  // Pty: the slave device path ("/dev/pts/7"), empty while unplugged. Tcp: "tcp://HOST:PORT".
  std::string device_path() const;
  // The pty symlink (options.pty_link), empty when none.
  std::string link_path() const;
  std::uint16_t tcp_port() const;

  // Disconnect fault. Pty: the pseudo-terminal is closed (a host holding it open gets EIO/hangup,
  // the device path disappears) and the symlink is removed. Tcp: the host is disconnected and the
  // listener closed. The device loses power. Returns after it happened.
  void unplug();
  // A new pseudo-terminal (a new device path; the symlink is re-pointed atomically) or the listener
  // again, with the device in its power-on state. Returns after it happened.
  void replug();
  bool plugged() const;

  SimCounters counters() const;
  void set_faults(const FaultConfig& faults);
  // Stop sending for `duration` from now.
  void stall(std::chrono::milliseconds duration);
  // Runs fn on the device under the server's lock (state queries and tweaks in tests).
  void with_device(const std::function<void(VirtualLidar&)>& fn);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// CLOCK_MONOTONIC in ns: the clock SimServer drives the device with and stamps zero packets with.
std::int64_t monotonic_ns();

}  // namespace ydscope
