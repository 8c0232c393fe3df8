#pragma once
// A worker thread that handles the newest item only: at most one item waits; a newer one
// replaces it (the replaced one counts as dropped). The node's continuous mode runs its
// segmentation on one of these, so a slow segmentation never builds up a backlog of clouds.
// With a minimum period, items start at most that often (the node's ~max_rate): a 30 Hz
// camera need not keep a core busy; what arrives meanwhile replaces the waiting item.
// ROS-free (std only): unit-tested without a master.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace symmetry_segmentation {

template <class Item>
class NewestItemWorker {
 public:
  using Handler = std::function<void(Item&)>;

  /// Starts the thread; `handler` runs on it for every item taken, one at a time. It must not
  /// throw (the thread would end the process).
  explicit NewestItemWorker(Handler handler) : handler_(std::move(handler)), thread_([this] { run(); }) {}
  ~NewestItemWorker() { stop(); }
  NewestItemWorker(const NewestItemWorker&) = delete;
  NewestItemWorker& operator=(const NewestItemWorker&) = delete;

  /// Hands `item` to the worker. An item still waiting is replaced (and counted as dropped).
  /// Ignored after stop().
  void push(Item item) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) return;
      if (pending_) ++dropped_;
      pending_ = std::move(item);
    }
    changed_.notify_one();
  }

  /// Items start at least `period` apart (zero: as soon as the last one is done).
  void setMinPeriod(std::chrono::steady_clock::duration period) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      min_period_ = period;
    }
    changed_.notify_all();
  }

  /// Forgets the waiting item, if any (not counted as dropped: it was withdrawn, not overtaken).
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.reset();
  }

  /// Forgets the waiting item, lets the item in progress finish and joins the thread. Idempotent.
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      pending_.reset();
    }
    changed_.notify_all();
    if (thread_.joinable() && thread_.get_id() != std::this_thread::get_id()) thread_.join();
  }

  /// Items replaced by a newer one before the worker took them.
  std::size_t dropped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return dropped_;
  }
  /// Items the handler has finished.
  std::size_t handled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return handled_;
  }
  /// True while an item waits or the handler runs.
  bool busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return pending_.has_value() || running_;
  }

 private:
  void run() {
    while (true) {
      std::optional<Item> item;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!stopping_) {
          if (!pending_) {
            changed_.wait(lock);
            continue;
          }
          const auto allowed = last_start_ + min_period_;
          if (std::chrono::steady_clock::now() >= allowed) break;
          changed_.wait_until(lock, allowed);  // a newer item may replace this one meanwhile
        }
        if (stopping_) return;
        item.swap(pending_);
        last_start_ = std::chrono::steady_clock::now();
        running_ = true;
      }
      handler_(*item);
      item.reset();  // release the item before counting it as handled
      {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = false;
        ++handled_;
      }
    }
  }

  Handler handler_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<Item> pending_;
  bool stopping_ = false;
  bool running_ = false;
  std::size_t dropped_ = 0;
  std::size_t handled_ = 0;
  std::chrono::steady_clock::duration min_period_{0};
  std::chrono::steady_clock::time_point last_start_{};
  std::thread thread_;  // last: starts after every other member exists
};

}  // namespace symmetry_segmentation
