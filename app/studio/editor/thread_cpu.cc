#include "app/studio/editor/thread_cpu.h"

#include <pthread.h>
#include <time.h>

#include <filesystem>
#include <fstream>
#include <map>

namespace procex::studio {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

std::vector<ThreadCpu> threads_cpu() {
  std::map<std::string, ThreadCpu> by_name;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream comm(task.path() / "comm"), schedstat(task.path() / "schedstat");
    std::string name;
    double run_ns = 0, wait_ns = 0;
    // A thread that ended meanwhile has no files left to read.
    if (!std::getline(comm, name) || !(schedstat >> run_ns >> wait_ns)) continue;
    ThreadCpu& t = by_name[name];
    t.name = name;
    t.cpu_ms += run_ns * 1e-6;
    t.waiting_ms += wait_ns * 1e-6;
  }
  std::vector<ThreadCpu> out;
  for (const auto& [name, t] : by_name) out.push_back(t);
  return out;
}

double threads_cpu_ms(const std::string& prefix) {
  double ms = 0;
  for (const ThreadCpu& t : threads_cpu())
    if (t.name.compare(0, prefix.size(), prefix) == 0) ms += t.cpu_ms;
  return ms;
}

void name_this_thread(const std::string& name) { pthread_setname_np(pthread_self(), name.substr(0, 15).c_str()); }

}  // namespace procex::studio
