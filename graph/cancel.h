// cancel.h -- a shared flag a caller sets to stop a running evaluation.
#pragma once

#include <atomic>
#include <memory>

namespace procex {

// Copies share the flag. Cancelled evaluations leave the cache as it was
// before the cancelled nodes ran: partial results are never stored.
class CancelToken {
 public:
  CancelToken() : flag_(std::make_shared<std::atomic<bool>>(false)) {}
  void cancel() const { flag_->store(true, std::memory_order_relaxed); }
  bool cancelled() const { return flag_->load(std::memory_order_relaxed); }
  void reset() const { flag_->store(false, std::memory_order_relaxed); }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
};

}  // namespace procex
