// The limits of one sweep() call in force (SweepBudget): what every state of
// an attempt makes (nested sweeps included) is counted, against one deadline
// for all attempts. The deadline is in the CPU time of the thread that made
// the Budget (a sweep runs on one thread): on a busy machine wall time passes
// while the sweep waits for a core, so a wall-clock deadline would refuse a
// footprint there that a quiet machine passes, and a batch's output would
// follow the machine's load.
#pragma once

#include <cstddef>

#include "core/sweep/sweep.h"

namespace procex::engine {

class Budget {
 public:
  // A plan of fewer than kClockedFromTheStart vertices starts its clock at
  // the first read (after kClockStride batches), not here: most such sweeps
  // never read it at all: on this VM the read (a system call) was a fifth of
  // the time of the OSM corpus's 9,491 small roofs and a tenth of the city's
  // 6,000. Their first batches take microseconds, so a runaway is refused as
  // before, that much later.
  Budget(const SweepBudget& limits, std::size_t plan_vertices);

  // A new attempt (another tolerance): its vertices and events count afresh.
  void start_attempt() { vertices_ = corners_ = events_ = 0; }
  // Each throws SweepBudgetError past its limit, at sweep height `z`.
  void add_vertex(double z) {
    if (++vertices_ > limits_.max_vertices && limits_.max_vertices > 0) vertices_exceeded(z);
  }
  // Corners are counted apart against the same limit: corners made at one
  // point share its vertex, so a sweep running away there (a jittered star's
  // centre) makes corners, and memory, without vertices.
  void add_corner(double z) {
    if (++corners_ > limits_.max_vertices && limits_.max_vertices > 0) corners_exceeded(z);
  }
  // A batch's candidates (every potential event at one height) are held at
  // once, and so are their collisions: they too are held to the vertex limit.
  // Where thousands of corners race through one point within delta2 (a
  // jittered star's apex) each meets every plane there, a batch of corners
  // times planes, many GB, that no other limit saw.
  void hold_candidates(std::size_t n, double z) const {
    if (n > limits_.max_vertices && limits_.max_vertices > 0) candidates_exceeded(z);
  }
  void add_events(std::size_t n, double z) {
    events_ += n;
    if (events_ > limits_.max_events && limits_.max_events > 0) events_exceeded(z);
  }
  // Reads the clock only every few calls: it is called once per event batch
  // and per list or group of a large one (and the thread's CPU clock is a
  // system call, not the vDSO).
  void check_time(double z) {
    if (++since_clock_ < kClockStride || !(limits_.max_seconds > 0.0)) return;
    since_clock_ = 0;
    const double now = thread_cpu_seconds();
    if (!deadline_) deadline_ = now + limits_.max_seconds;
    if (now > deadline_) time_exceeded(z);
  }

  static constexpr std::size_t kClockStride = 64;
  static constexpr std::size_t kClockedFromTheStart = 256;

 private:
  static double thread_cpu_seconds();
  [[noreturn]] void vertices_exceeded(double z) const;
  [[noreturn]] void corners_exceeded(double z) const;
  [[noreturn]] void candidates_exceeded(double z) const;
  [[noreturn]] void events_exceeded(double z) const;
  [[noreturn]] void time_exceeded(double z) const;

  SweepBudget limits_;
  double deadline_;  // in thread_cpu_seconds(); 0 until the clock is first read
  std::size_t vertices_ = 0, corners_ = 0, events_ = 0, since_clock_ = 0;
};

}  // namespace procex::engine
