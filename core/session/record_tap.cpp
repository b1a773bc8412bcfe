#include "core/session/record_tap.h"

namespace ydscope {

bool RecordTap::push(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns) {
  {
    std::lock_guard lock(mutex_);
    if (closed_) return false;
    if (queued_bytes_ + payload.size() > max_bytes_) {
      ++dropped_;
      return false;
    }
    if (free_.empty()) {
      queue_.emplace_back();
    } else {
      queue_.push_back(std::move(free_.back()));
      free_.pop_back();
    }
    TapRecord& record = queue_.back();
    record.type = type;
    record.t_ns = t_ns;
    record.payload.assign(payload.begin(), payload.end());
    queued_bytes_ += payload.size();
  }
  ready_.notify_one();
  return true;
}

void RecordTap::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

bool RecordTap::wait_and_take(std::vector<TapRecord>& out, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return !queue_.empty() || closed_; });
  for (auto& record : queue_) out.push_back(std::move(record));
  queue_.clear();
  queued_bytes_ = 0;
  return !(closed_ && out.empty());
}

void RecordTap::recycle(std::vector<TapRecord>& records) {
  std::lock_guard lock(mutex_);
  for (auto& record : records) free_.push_back(std::move(record));
  records.clear();
}

std::uint64_t RecordTap::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

}  // namespace ydscope
