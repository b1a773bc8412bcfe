#include "core/stream/lap_stream.h"

#include <algorithm>
#include <mutex>

namespace ydscope {

// What a stream and its subscriptions share, so either may go first.
struct LapSubscription::Hub {
  std::mutex mutex;
  std::vector<LapSubscription*> consumers;  // attached, in the order they subscribed
};

LapSubscription::LapSubscription(std::shared_ptr<Hub> hub, std::string name, std::size_t capacity, WakeFn wake)
    : hub_(std::move(hub)), name_(std::move(name)), ring_(capacity), wake_(std::move(wake)) {}

LapSubscription::~LapSubscription() {
  std::lock_guard lock(hub_->mutex);
  auto& list = hub_->consumers;
  list.erase(std::remove(list.begin(), list.end(), this), list.end());
}

LapConsumerStats LapSubscription::stats() const {
  return {name_, ring_.capacity(), ring_.pushed(), ring_.dropped_full(), ring_.skipped()};
}

void LapSubscription::deliver(const Lap& lap) {
  if (ring_.try_push(lap) && wake_) wake_();
}

LapStream::LapStream() : hub_(std::make_shared<LapSubscription::Hub>()) {}

LapStream::~LapStream() {
  std::lock_guard lock(hub_->mutex);
  hub_->consumers.clear();
}

std::unique_ptr<LapSubscription> LapStream::subscribe(std::string name, std::size_t capacity,
                                                      LapSubscription::WakeFn wake) {
  // The ring (and every lap slot in it) is made before the producer can see it.
  std::unique_ptr<LapSubscription> subscription(new LapSubscription(hub_, std::move(name), capacity, std::move(wake)));
  std::lock_guard lock(hub_->mutex);
  hub_->consumers.push_back(subscription.get());
  return subscription;
}

void LapStream::publish(const Lap& lap) {
  std::lock_guard lock(hub_->mutex);
  for (LapSubscription* consumer : hub_->consumers) consumer->deliver(lap);
}

std::vector<LapConsumerStats> LapStream::stats() const {
  std::lock_guard lock(hub_->mutex);
  std::vector<LapConsumerStats> all;
  all.reserve(hub_->consumers.size());
  for (const LapSubscription* consumer : hub_->consumers) all.push_back(consumer->stats());
  return all;
}

}  // namespace ydscope
