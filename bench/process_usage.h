// What this process has used so far, as the benchmarks' tables report it.
#pragma once

#include <sys/resource.h>

#include <ctime>

namespace procex::bench {

// CPU seconds of the whole process (every thread): what a busy machine's
// waiting leaves out of a wall-clock time.
inline double cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// The peak resident set so far, in MB (ru_maxrss is in KiB on Linux).
inline double peak_rss_mb() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace procex::bench
