#include "app/gui/replay_source.h"

#include <cstdio>

#include "core/record/recording_plan.h"

namespace ydscope::gui {
namespace {

// The session owns its link as a unique_ptr; this forwards to a shared ReplayLink so the UI can
// reach the replay controls through a weak pointer without owning the link.
class SharedReplayLink final : public ByteLink {
 public:
  explicit SharedReplayLink(std::shared_ptr<ReplayLink> link) : link_(std::move(link)) {}
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    link_->async_read_some(buffer, std::move(handler));
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    link_->async_write(bytes, std::move(handler));
  }
  void close() override { link_->close(); }
  bool set_baud(std::uint32_t baud, std::string& error) override { return link_->set_baud(baud, error); }
  bool accepts_commands() const override { return link_->accepts_commands(); }
  std::string describe() const override { return link_->describe(); }
  const RecordingMetadata* recording_metadata() const override { return link_->recording_metadata(); }

 private:
  std::shared_ptr<ReplayLink> link_;
};

}  // namespace

void ReplayHandle::set(const std::shared_ptr<ReplayLink>& link) {
  std::lock_guard lock(mutex_);
  link_ = link;
}

std::shared_ptr<ReplayLink> ReplayHandle::lock() const {
  std::lock_guard lock(mutex_);
  return link_.lock();
}

std::optional<ReplayStatus> ReplayHandle::status() const {
  if (auto link = lock()) return link->status();
  return std::nullopt;
}

void ReplayHandle::set_paused(bool paused) {
  if (auto link = lock()) link->set_paused(paused);
}

void ReplayHandle::set_speed(double speed) {
  if (auto link = lock()) link->set_speed(speed);
}

void ReplayHandle::set_loop(bool loop) {
  if (auto link = lock()) link->set_loop(loop);
}

std::optional<SessionConfig> replay_config(const std::string& path, const std::optional<std::string>& model,
                                           ReplayOptions options, std::shared_ptr<ReplayHandle> handle,
                                           std::string& error, std::vector<std::string>& warnings) {
  const RecordingPlan plan = plan_recording(path, RecordingUse::Replay, model, std::nullopt);
  if (!plan.usable()) {
    error = plan.refusal_text;
    return std::nullopt;
  }
  warnings = plan.warnings();
  SessionConfig config;
  config.address = path;
  config.model = plan.profile->model;
  config.distance_scale = plan.distance_scale;
  // A replay never reconnects: a file that does not open now will not open in 4 s either (once
  // it retried forever), and one that played to its end is finished.
  config.reconnect = false;
  // As ydscope-cli replay says it; the view shows it too (SourceSlot::describe_view).
  options.on_gap = [](const RecordingGap& gap, bool skipped) {
    std::fprintf(stderr, "ydscope: %s\n", gap_sentence(gap, skipped).c_str());
  };
  config.open_link = [path, options, handle](boost::asio::io_context& io, std::uint32_t,
                                             std::string& open_error) -> std::unique_ptr<ByteLink> {
    std::shared_ptr<ReplayLink> link = ReplayLink::open(io, path, options, open_error);
    if (!link) return nullptr;
    handle->set(link);
    return std::make_unique<SharedReplayLink>(std::move(link));
  };
  return config;
}

}  // namespace ydscope::gui
