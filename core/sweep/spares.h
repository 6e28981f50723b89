// Storage a thread's finished sweep leaves to its next. A batch sweeps its
// footprints one after another on one thread (the city's 6,000, of 4-200
// corners each); every sweep growing its arrays and lists from empty made
// some 900,000 of the city's 2.6 million allocations, each growth copying
// what it had into memory not yet in the cache, and glibc consolidated the
// small chunks the sweep before had freed whenever one grew past 1 KB
// (issue 12).
#pragma once

#include <array>
#include <cstddef>
#include <memory>

namespace procex::engine {

// Scratch of a sweep of more corners than this is freed, not kept: one large
// plan would otherwise leave its lists' memory held for the thread's life.
inline constexpr std::size_t kSpareUpTo = 4096;

// Up to two spare T per thread: a sweep's and the nested sweep's of a
// horizontal step.
template <class T>
class Spares {
 public:
  // A spare T as its last user left it, or a new one.
  static std::unique_ptr<T> take() {
    if (count_ == 0) return std::make_unique<T>();
    return std::move(spares_[--count_]);
  }
  // Keeps t for the thread's next sweep if the sweep that used it made at
  // most kSpareUpTo corners and there is room; frees it otherwise.
  static void give(std::unique_ptr<T> t, std::size_t corners) noexcept {
    if (corners <= kSpareUpTo && count_ < kKept) spares_[count_++] = std::move(t);
  }

 private:
  static constexpr std::size_t kKept = 2;
  static inline thread_local std::array<std::unique_ptr<T>, kKept> spares_;
  static inline thread_local std::size_t count_ = 0;
};

}  // namespace procex::engine
