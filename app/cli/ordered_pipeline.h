// Items made one at a time in order, worked on in parallel, and handed to a
// consumer on another thread in that order: a batch's buildings read from
// their spool, evaluated, and yielded in input order (procex.batch_iter).
// Unlike windows that each wait for their slowest item, the workers keep
// going past a slow item while the consumer waits for it in order; what they
// may hold is bounded, so memory is too: at most `ahead` items made and not
// yet in order (TBB's tokens), and `ahead` more in order and not yet taken.
//
// The pipeline runs on a thread of its own (named, for top -H), inside the
// arena given; make() and work() run on that thread and the arena's workers,
// never on the consumer's. An exception from either stops the pipeline; the
// consumer gets those of the items before it that were already in order, then
// the exception.
#pragma once

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/task_arena.h>

namespace procex {

template <class Item>
class OrderedPipeline {
 public:
  // make(i): the i-th item, called in order, one at a time. work(item): in
  // parallel; it should return soon once stopping() (close() was called).
  OrderedPipeline(std::size_t count, std::size_t ahead, tbb::task_arena& arena, std::function<Item(std::size_t)> make,
                  std::function<void(Item&)> work, const std::string& thread_name)
      : count_(count), ahead_(ahead > 0 ? ahead : 1), arena_(arena), make_(std::move(make)), work_(std::move(work)) {
    thread_ = std::thread([this] { run(); });
    pthread_setname_np(thread_.native_handle(), thread_name.substr(0, 15).c_str());  // Linux: 15 characters
  }
  OrderedPipeline(const OrderedPipeline&) = delete;
  OrderedPipeline& operator=(const OrderedPipeline&) = delete;
  ~OrderedPipeline() { close(); }

  enum class Next { kItem, kEnd, kWaiting };
  // The next item in order into `out` (kItem); kEnd after the last one or
  // once closed, rethrowing make's or work's exception if one stopped it;
  // kWaiting if none came within `wait`.
  Next next(Item& out, std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, wait, [&] { return !ready_.empty() || finished_; });
    if (!ready_.empty()) {
      out = std::move(*ready_.front());
      ready_.pop_front();
      changed_.notify_all();
      return Next::kItem;
    }
    if (!finished_) return Next::kWaiting;
    if (std::exception_ptr error = std::exchange(error_, nullptr)) std::rethrow_exception(error);
    return Next::kEnd;
  }

  bool stopping() const { return stop_; }

  // Stops making items, drops those not taken and joins the thread (an item
  // in work() finishes first). Idempotent.
  void close() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
      changed_.notify_all();
    }
    if (thread_.joinable()) thread_.join();
    std::lock_guard lock(mutex_);
    ready_.clear();
    finished_ = true;
  }

 private:
  using Owned = std::unique_ptr<Item>;

  // Items travel through TBB by index, each in the slot `index % ahead_`:
  // at most `ahead_` tokens are in flight and the last filter runs in order,
  // so item i + ahead_ is made only after item i has left its slot. TBB does
  // not destroy the objects its filters hold when an exception cancels the
  // pipeline (LeakSanitizer found the items in flight lost), so it holds
  // none.
  void run() {
    std::size_t made = 0;
    std::vector<Owned> slots(ahead_);
    try {
      arena_.execute([&] {
        tbb::parallel_pipeline(
            ahead_,
            tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                                [&](tbb::flow_control& fc) -> std::size_t {
                                                  if (stop_ || made == count_) {
                                                    fc.stop();
                                                    return 0;
                                                  }
                                                  slots[made % ahead_] = std::make_unique<Item>(make_(made));
                                                  return made++;
                                                }) &
                tbb::make_filter<std::size_t, std::size_t>(tbb::filter_mode::parallel,
                                                           [&](std::size_t i) {
                                                             if (!stop_) work_(*slots[i % ahead_]);
                                                             return i;
                                                           }) &
                // In order; waits while `ahead_` are ready and not taken, so the
                // tokens that finish meanwhile wait in TBB's buffer, bounded too.
                tbb::make_filter<std::size_t, void>(tbb::filter_mode::serial_in_order, [&](std::size_t i) {
                  Owned item = std::move(slots[i % ahead_]);
                  std::unique_lock lock(mutex_);
                  changed_.wait(lock, [&] { return stop_ || ready_.size() < ahead_; });
                  if (stop_) return;
                  ready_.push_back(std::move(item));
                  changed_.notify_all();
                }));
      });
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
    }
    std::lock_guard lock(mutex_);
    finished_ = true;
    changed_.notify_all();
  }

  const std::size_t count_, ahead_;
  tbb::task_arena& arena_;
  std::function<Item(std::size_t)> make_;
  std::function<void(Item&)> work_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Owned> ready_;
  bool finished_ = false;
  std::exception_ptr error_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace procex
