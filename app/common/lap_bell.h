#pragma once
// The I/O thread rings after every lap it queues (Session's wake callback); a command-line
// consumer sleeps on the bell instead of polling the queue.
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace ydscope {

struct LapBell {
  std::mutex mutex;
  std::condition_variable rang;
  bool pending = false;
  void ring() {
    {
      std::lock_guard lock(mutex);
      pending = true;
    }
    rang.notify_one();
  }
  void wait(std::chrono::milliseconds at_most) {
    std::unique_lock lock(mutex);
    rang.wait_for(lock, at_most, [this] { return pending; });
    pending = false;
  }
};

}  // namespace ydscope
