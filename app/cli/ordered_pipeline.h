// Items made one at a time in order, worked on in parallel, and finished
// one at a time in that order, with at most `ahead` of them between made and
// finished: a batch's buildings read from their spool, evaluated, and written
// or handed over in input order. Unlike windows that each wait for their
// slowest item, the workers keep going past a slow item while its turn to be
// finished waits for it, and memory stays bounded by `ahead`.
//
// run_in_order finishes the items in the calling thread's arena (procex
// batch writes them there). OrderedPipeline hands them to a consumer on
// another thread (procex.batch_iter: Python's thread): it runs on a thread of
// its own (named, for top -H), inside the arena given; make() and work() run
// on that thread and the arena's workers, never on the consumer's. It holds at
// most `ahead` items made and not yet in order (TBB's tokens), and `ahead`
// more in order and not yet taken. An exception from make or work stops the
// pipeline; the consumer gets those of the items before it that were already
// in order, then the exception.
#pragma once

#include <pthread.h>

#include <algorithm>
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

// make(i): the i-th item, called in order, one at a time, until `stopped()`;
// work(item): in parallel; finish(item): in order, one at a time. Items
// travel through TBB by index, each in the slot `index % ahead`: at most
// `ahead` tokens are in flight and the last filter runs in order, so item
// i + ahead is made only after item i has left its slot. TBB does not destroy
// the objects its filters hold when an exception cancels the pipeline
// (LeakSanitizer found the items in flight lost), so it holds none. An
// exception from any of them stops the items not yet made and is rethrown.
template <class Item>
void run_in_order(std::size_t count, std::size_t ahead, const std::function<Item(std::size_t)>& make,
                  const std::function<void(Item&)>& work, const std::function<void(Item&)>& finish,
                  const std::function<bool()>& stopped) {
  ahead = std::max<std::size_t>(ahead, 1);
  std::size_t made = 0;
  std::vector<std::unique_ptr<Item>> slots(ahead);
  tbb::parallel_pipeline(
      ahead,
      tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                          [&](tbb::flow_control& fc) -> std::size_t {
                                            if (made == count || stopped()) {
                                              fc.stop();
                                              return 0;
                                            }
                                            slots[made % ahead] = std::make_unique<Item>(make(made));
                                            return made++;
                                          }) &
          tbb::make_filter<std::size_t, std::size_t>(tbb::filter_mode::parallel,
                                                     [&](std::size_t i) {
                                                       work(*slots[i % ahead]);
                                                       return i;
                                                     }) &
          tbb::make_filter<std::size_t, void>(tbb::filter_mode::serial_in_order, [&](std::size_t i) {
            const std::unique_ptr<Item> item = std::move(slots[i % ahead]);
            finish(*item);
          }));
}

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

  void run() {
    try {
      arena_.execute([&] {
        run_in_order<Item>(
            count_, ahead_, make_, [&](Item& item) { if (!stop_) work_(item); },
            // Waits while `ahead_` are ready and not taken, so the tokens that
            // finish meanwhile wait in TBB's buffer, bounded too.
            [&](Item& item) {
              std::unique_lock lock(mutex_);
              changed_.wait(lock, [&] { return stop_ || ready_.size() < ahead_; });
              if (stop_) return;
              ready_.push_back(std::make_unique<Item>(std::move(item)));
              changed_.notify_all();
            },
            [&] { return stop_.load(); });
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
