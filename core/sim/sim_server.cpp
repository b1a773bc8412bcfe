#include "core/sim/sim_server.h"

#include <sys/eventfd.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/sim/line_writer.h"
#include "core/sim/pty_endpoint.h"
#include "core/sim/tcp_endpoint.h"

namespace ydscope {

std::int64_t monotonic_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

namespace {
constexpr std::int64_t kMaxWaitNs = 100'000'000;     // re-check stop and schedules at least this often
constexpr std::int64_t kRecheckWaitNs = 20'000'000;  // a pty without a host is re-checked this often
constexpr std::int64_t kNever = VirtualLidar::kNever;
}  // namespace

class SimServer::Impl {
 public:
  explicit Impl(SimServerOptions opts) : options(std::move(opts)) {}

  void run();
  void handle_requests_locked(std::int64_t now);
  void unplug_locked(std::int64_t now);
  void replug_locked(std::int64_t now);
  void write_out(const std::vector<std::uint8_t>& out, const std::vector<std::size_t>& zero_ends,
                 const std::vector<std::size_t>* piece_ends = nullptr);
  void shape(std::int64_t now, const std::vector<std::uint8_t>& out, const std::vector<std::size_t>& zero_ends);
  void wake() const {
    const std::uint64_t one = 1;
    if (wake_fd >= 0) (void)!::write(wake_fd, &one, sizeof one);
  }
  void post_and_wait(std::unique_lock<std::mutex>& lock, int request);
  void log_line(std::int64_t t_ns, std::string_view line) const {
    if (!options.on_log) return;
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.3f ", static_cast<double>(t_ns - started_ns) * 1e-9);
    options.on_log(std::string(stamp) + std::string(line));
  }

  SimServerOptions options;
  mutable std::mutex mu;
  std::condition_variable cv;
  std::unique_ptr<VirtualLidar> device;
  std::unique_ptr<DeliveryShaper> shaper;      // null for DeliveryKind::Whole
  std::deque<std::uint64_t> shaped_zero_ends;  // stream offsets of zero-packet ends still held
  std::uint64_t shaped_in = 0;                 // bytes given to the shaper so far
  std::uint64_t shaped_out = 0;                // bytes it has released so far
  std::unique_ptr<SimEndpoint> endpoint;       // the server thread's, or start/stop's while it is not running
  std::thread thread;
  int wake_fd = -1;
  bool running = false;
  bool stop_requested = false;
  int request = 0;  // 0 none, 1 unplug, 2 replug
  std::uint64_t request_seq = 0;
  std::uint64_t done_seq = 0;
  std::string request_error;
  SimServerCounters counters;
  std::string device_path;
  std::uint16_t tcp_port = 0;
  std::int64_t started_ns = 0;
  // The device's clock: CLOCK_MONOTONIC since start, times options.time_scale. Every time the
  // device and the scheduled faults see is on it; only waits (and zero-packet stamps) are wall.
  std::int64_t now() const {
    const std::int64_t wall = monotonic_ns() - started_ns;
    if (options.time_scale == 1.0) return started_ns + wall;
    return started_ns + static_cast<std::int64_t>(static_cast<double>(wall) * options.time_scale);
  }
  std::int64_t wall_wait(std::int64_t device_ns) const {
    if (options.time_scale == 1.0) return device_ns;
    return static_cast<std::int64_t>(static_cast<double>(device_ns) / options.time_scale);
  }
  std::int64_t unplug_at = kNever;
  std::int64_t replug_at = kNever;
  LineWriter line_out{options.on_zero_packet_written};
};

void SimServer::Impl::unplug_locked(std::int64_t now) {
  if (!endpoint) return;
  endpoint.reset();  // closes the pty or the sockets; removes the link
  device->power_cycle(now);
  if (shaper) {  // the bridge lost power with the device
    shaper->clear();
    shaped_zero_ends.clear();
    shaped_out = shaped_in;
  }
  device_path.clear();
  ++counters.unplugs;
  log_line(now, "unplugged");
}

void SimServer::Impl::replug_locked(std::int64_t now) {
  if (endpoint) return;
  if (options.transport == SimTransport::Pty) {
    endpoint = std::make_unique<PtyEndpoint>(options.pty_link);
  } else {
    auto tcp = std::make_unique<TcpEndpoint>(options.tcp_host, tcp_port ? tcp_port : options.tcp_port);
    tcp_port = tcp->port();
    endpoint = std::move(tcp);
  }
  if (counters.unplugs > 0) device->power_cycle(now);  // a replug: the device lost power
  device_path = endpoint->device_path();
  log_line(now, "plugged in at " + device_path);
}

void SimServer::Impl::handle_requests_locked(std::int64_t now) {
  if (request != 0) {
    request_error.clear();
    try {
      if (request == 1) unplug_locked(now);
      if (request == 2 && !endpoint) {
        replug_locked(now);
        ++counters.replugs;
      }
    } catch (const std::exception& error) {
      request_error = error.what();
    }
    request = 0;
    done_seq = request_seq;
    cv.notify_all();
  }
  if (unplug_at <= now) {
    unplug_at = kNever;
    unplug_locked(now);
    if (options.replug_after.count() > 0) replug_at = now + options.replug_after.count() * 1'000'000;
  }
  if (replug_at <= now) {
    replug_at = kNever;
    try {
      replug_locked(now);
      ++counters.replugs;
    } catch (const std::exception& error) {
      log_line(now, std::string("replug failed: ") + error.what());
    }
  }
}

void SimServer::Impl::write_out(const std::vector<std::uint8_t>& out, const std::vector<std::size_t>& zero_ends,
                                const std::vector<std::size_t>* piece_ends) {
  const LineWriter::Totals totals = line_out.write(endpoint.get(), out, zero_ends, piece_ends);
  std::lock_guard lock(mu);
  counters.bytes_written += totals.written;
  counters.bytes_unheard += totals.unheard;
  counters.zero_packets_written += totals.zero_packets;
  counters.laps_overrun += totals.laps_overrun;
}

void SimServer::Impl::shape(std::int64_t now, const std::vector<std::uint8_t>& out,
                            const std::vector<std::size_t>& zero_ends) {
  for (const std::size_t end : zero_ends) shaped_zero_ends.push_back(shaped_in + end);
  shaped_in += out.size();
  shaper->push(now, out);
  std::vector<std::uint8_t> shaped;
  std::vector<std::size_t> piece_ends;
  shaper->pop(now, shaped, piece_ends);
  if (shaped.empty()) return;
  std::vector<std::size_t> shaped_zeros;
  while (!shaped_zero_ends.empty() && shaped_zero_ends.front() <= shaped_out + shaped.size()) {
    shaped_zeros.push_back(static_cast<std::size_t>(shaped_zero_ends.front() - shaped_out));
    shaped_zero_ends.pop_front();
  }
  shaped_out += shaped.size();
  write_out(shaped, shaped_zeros, &piece_ends);
}

void SimServer::Impl::run() {
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> host;
  std::vector<std::size_t> zero_ends;
  std::vector<pollfd> fds;
  for (;;) {
    std::int64_t next = kNever;
    out.clear();
    zero_ends.clear();
    {
      std::lock_guard lock(mu);
      if (stop_requested) break;
      const std::int64_t now = this->now();
      handle_requests_locked(now);
      device->produce(now, out, &zero_ends);
      next = std::min({device->next_event_ns(), unplug_at, replug_at});
    }
    if (shaper) {
      shape(now(), out, zero_ends);  // on the device clock, like next; the shaper is this thread's alone
      next = std::min(next, shaper->next_due_ns());
    } else if (!out.empty()) {
      write_out(out, zero_ends);
    }

    fds.clear();
    fds.push_back({wake_fd, POLLIN, 0});
    bool recheck = false;
    if (endpoint) {
      endpoint->poll_fds(fds);
      recheck = endpoint->needs_recheck();
    }
    std::int64_t wait = next == kNever ? kMaxWaitNs : std::clamp<std::int64_t>(wall_wait(next - now()), 0, kMaxWaitNs);
    if (recheck) wait = std::min(wait, kRecheckWaitNs);
    const timespec timeout{static_cast<time_t>(wait / 1'000'000'000), static_cast<long>(wait % 1'000'000'000)};
    if (::ppoll(fds.data(), fds.size(), &timeout, nullptr) < 0 && errno != EINTR) break;
    if (fds[0].revents & POLLIN) {
      std::uint64_t value = 0;
      (void)!::read(wake_fd, &value, sizeof value);
    }
    host.clear();
    std::lock_guard lock(mu);
    if (endpoint) endpoint->service(std::span<const pollfd>(fds).subspan(1), host, counters);
    if (!host.empty()) {
      counters.bytes_in += host.size();
      device->receive(host, now());
    }
  }
}

void SimServer::Impl::post_and_wait(std::unique_lock<std::mutex>& lock, int what) {
  request = what;
  const std::uint64_t seq = ++request_seq;
  wake();
  cv.wait(lock, [&] { return done_seq >= seq || !running; });
  if (!request_error.empty()) throw std::runtime_error(request_error);
}

SimServer::SimServer(SimServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

SimServer::~SimServer() { stop(); }

void SimServer::start() {
  Impl& s = *impl_;
  std::lock_guard lock(s.mu);
  if (s.running) return;
  s.started_ns = monotonic_ns();
  s.device = std::make_unique<VirtualLidar>(s.options.device, s.started_ns);
  s.device->set_log([&s](std::int64_t t, std::string_view line) { s.log_line(t, line); });
  s.shaper.reset();
  if (s.options.delivery.kind != DeliveryKind::Whole)
    s.shaper = std::make_unique<DeliveryShaper>(s.options.delivery, s.device->profile().default_baud,
                                                s.options.device.seed, s.started_ns);
  s.shaped_zero_ends.clear();
  s.shaped_in = s.shaped_out = 0;
  if (!s.options.zero_packet_log.empty()) s.line_out.open_zero_log(s.options.zero_packet_log);
  try {
    s.replug_locked(s.started_ns);
  } catch (...) {
    s.line_out.close_zero_log();
    throw;
  }
  s.wake_fd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  s.unplug_at = s.options.unplug_after.count() > 0 ? s.started_ns + s.options.unplug_after.count() * 1'000'000 : kNever;
  s.replug_at = kNever;
  s.stop_requested = false;
  s.running = true;
  s.thread = std::thread([&s] { s.run(); });
}

void SimServer::stop() {
  Impl& s = *impl_;
  {
    std::lock_guard lock(s.mu);
    if (!s.running) return;
    s.stop_requested = true;
    s.wake();
  }
  s.thread.join();
  std::lock_guard lock(s.mu);
  s.endpoint.reset();
  s.device_path.clear();
  if (s.wake_fd >= 0) ::close(s.wake_fd);
  s.wake_fd = -1;
  s.line_out.close_zero_log();
  s.running = false;
  s.cv.notify_all();
}

bool SimServer::running() const {
  std::lock_guard lock(impl_->mu);
  return impl_->running;
}

std::string SimServer::device_path() const {
  std::lock_guard lock(impl_->mu);
  return impl_->device_path;
}

std::string SimServer::link_path() const { return impl_->options.pty_link; }

std::uint16_t SimServer::tcp_port() const {
  std::lock_guard lock(impl_->mu);
  return impl_->tcp_port;
}

void SimServer::unplug() {
  std::unique_lock lock(impl_->mu);
  if (!impl_->running) throw std::logic_error("SimServer::unplug needs a started server");
  impl_->post_and_wait(lock, 1);
}

void SimServer::replug() {
  std::unique_lock lock(impl_->mu);
  if (!impl_->running) throw std::logic_error("SimServer::replug needs a started server");
  impl_->post_and_wait(lock, 2);
}

bool SimServer::plugged() const {
  std::lock_guard lock(impl_->mu);
  return !impl_->device_path.empty();
}

SimCounters SimServer::counters() const {
  std::lock_guard lock(impl_->mu);
  SimCounters c;
  if (impl_->device) {
    c.device = impl_->device->counters();
    c.faults = impl_->device->fault_counters();
  }
  c.server = impl_->counters;
  return c;
}

void SimServer::set_faults(const FaultConfig& faults) {
  std::lock_guard lock(impl_->mu);
  if (impl_->device) impl_->device->set_faults(faults);
  impl_->wake();
}

void SimServer::stall(std::chrono::milliseconds duration) {
  std::lock_guard lock(impl_->mu);
  if (impl_->device) impl_->device->stall(impl_->now(), duration.count() * 1'000'000);
}

void SimServer::with_device(const std::function<void(VirtualLidar&)>& fn) {
  std::lock_guard lock(impl_->mu);
  if (!impl_->device) throw std::logic_error("SimServer::with_device needs a started server");
  fn(*impl_->device);
  impl_->wake();
}

}  // namespace ydscope
