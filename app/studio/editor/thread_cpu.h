// thread_cpu.h -- CPU time of this process's threads, for the frame report
// (--report-frames): on a shared, loaded machine a frame's wall time counts
// the time its threads waited for a core, its CPU time only what they ran.
// Splitting the process's CPU time by thread tells the UI thread's work from
// the evaluation thread's and from the software rasteriser's own threads
// (Mesa's llvmpipe-N).
#pragma once

#include <string>
#include <vector>

namespace procex::studio {

// CPU time (user + system) the calling thread has used, in milliseconds.
double thread_cpu_ms();

struct ThreadCpu {
  std::string name;       // the thread's name (/proc/self/task/N/comm)
  double cpu_ms = 0;      // time it ran
  double waiting_ms = 0;  // time it was ready to run but waited for a core (the load's share)
};
// Every live thread of this process, from the scheduler's nanosecond
// counters (/proc/self/task/N/schedstat), threads of the same name added up.
std::vector<ThreadCpu> threads_cpu();
// The CPU time used so far by the threads whose names start with `prefix`
// (Mesa's software rasteriser: "llvmpipe-").
double threads_cpu_ms(const std::string& prefix);

// Names the calling thread as `top` and /proc show it (at most 15 characters).
void name_this_thread(const std::string& name);

}  // namespace procex::studio
