// How procex's time and memory grow with the input (BENCHMARKS "Scale",
// issue 18), beside CGAL 5.5's create_interior_straight_skeleton_2 and, when
// given its binary, Surfer2 in the same run: every file bench/scale_inputs.py
// wrote, every edge at 45 degrees.
//
// Each measurement runs in a child process of its own, so its peak resident
// set (wait4's ru_maxrss) is that engine's alone on that input, and a runaway
// is stopped by a CPU-time and address-space limit instead of taking the
// machine. Times are CPU seconds of the child (the machine may be shared);
// procex is timed as sweep() alone and as the `procex roof` pipeline
// (sweep, mesh, validate). Surfer2 (Palfrader, Held and Huber's kinetic
// triangulation, issue 18's yardstick; GPL-3, so never part of this
// repository: bench/surfer2_build.sh builds it from a checkout) is its own
// process, timed whole: reading the GraphML this program writes for it from the
// prepared footprint, the skeleton, writing its .obj. Once an engine runs out
// of CPU time or memory on a family, its larger inputs are not tried; after
// other failures (an invalid roof, a refusal, a crash) they still are: those
// come from an input's own degeneracies (Surfer2 in double arithmetic stops
// on some), so a larger input may pass, and the limits bound what it costs.
// The log-log slope of time against n is fitted per family and engine over
// n >= 4096.
//
//   procex_scale_bench [--budget SECONDS] [--memory-gb GB] [--no-cgal] [--surfer2 SURFER] DIR
#include <fcntl.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "bench/process_usage.h"
#include "core/geom/prepare.h"
#include "core/io/polyjson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/support/cgal_skeleton.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using bench::cpu_seconds;

enum class Engine { Sweep, Roof, Cgal, Surfer2 };
const char* engine_name(Engine e) {
  switch (e) {
    case Engine::Sweep: return "procex sweep()";
    case Engine::Roof: return "procex roof (sweep+mesh+validate)";
    case Engine::Cgal: return "CGAL 5.5";
    case Engine::Surfer2: return "Surfer2 (double)";
  }
  return "?";
}

struct Input {
  std::string family;
  std::size_t n = 0;  // vertices in the file
  fs::path path;
};

// What a child reports through its pipe: a status word and, for the roof
// pipeline, whether the mesh validated.
struct ChildResult {
  char status[16] = "crashed";  // ok, invalid (roof only), refused, memory (past --memory-gb), budget (CPU), crashed
};

struct Measurement {
  std::string status;
  double cpu_s = 0.0;
  double peak_mb = 0.0;
};

Footprint read_footprint(const Input& in) {
  const std::vector<PolyShape> shapes = read_polyjson_file(in.path);
  return prepare_footprint(to_footprint(shapes.at(0), 45.0)).footprint;
}

// Surfer2 reads a plane straight-line graph as GraphML and, with
// --component=0, skeletonises only the face left of the graph's first edge:
// the prepared loops run with the interior on their left (outer boundaries
// counter-clockwise, holes clockwise), so that face is the interior procex
// sweeps, not the unbounded outside. %.17g round-trips, so both engines see
// the same polygon; an edge without a weight moves at speed 1, 45 degrees.
void write_surfer2_graphml(const Footprint& footprint, const fs::path& path) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  std::fprintf(f, "<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\">\n"
                  "<key attr.name=\"vertex-coordinate-x\" attr.type=\"string\" for=\"node\" id=\"x\"/>\n"
                  "<key attr.name=\"vertex-coordinate-y\" attr.type=\"string\" for=\"node\" id=\"y\"/>\n"
                  "<graph edgedefault=\"undirected\">\n");
  std::size_t id = 0;
  for (const Loop& loop : footprint.loops)
    for (const glm::dvec2& p : loop.points)
      std::fprintf(f, "<node id=\"%zu\"><data key=\"x\">%.17g</data><data key=\"y\">%.17g</data></node>\n", id++,
                   p.x, p.y);
  std::size_t first = 0;
  for (const Loop& loop : footprint.loops) {
    const std::size_t n = loop.points.size();
    for (std::size_t i = 0; i < n; ++i)
      std::fprintf(f, "<edge source=\"%zu\" target=\"%zu\"/>\n", first + i, first + (i + 1) % n);
    first += n;
  }
  std::fprintf(f, "</graph>\n</graphml>\n");
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path.string());
}

// Runs in the child: reads and prepares the input (not timed), then the engine.
ChildResult run_engine(const Input& in, Engine engine, double& engine_cpu_s) {
  ChildResult r;
  const Footprint footprint = read_footprint(in);
  const double start = cpu_seconds();
  std::snprintf(r.status, sizeof r.status, "ok");
  try {
    if (engine == Engine::Cgal) {
      const CgalSkeletonInput cgal(footprint);
      const double cgal_start = cpu_seconds();
      cgal.skeletonise();
      engine_cpu_s = cpu_seconds() - cgal_start;
      return r;
    }
    const Surface surface = sweep(footprint);
    if (engine == Engine::Roof && !validate(build_mesh(surface)).ok())
      std::snprintf(r.status, sizeof r.status, "invalid");
  } catch (const std::bad_alloc&) {
    std::snprintf(r.status, sizeof r.status, "memory");
  } catch (const std::exception&) {
    std::snprintf(r.status, sizeof r.status, "refused");
  }
  engine_cpu_s = cpu_seconds() - start;
  return r;
}

// Surfer2's run on one input: the files it reads and writes, in this
// program's scratch folder.
struct Surfer2Files {
  fs::path binary, graphml, obj;
};

Measurement measure(const Input& in, Engine engine, double budget_s, double memory_gb, const Surfer2Files& surfer2) {
  int fds[2];
  if (::pipe(fds) != 0) std::abort();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    const rlim_t cpu = static_cast<rlim_t>(std::ceil(budget_s));
    const rlimit cpu_limit{cpu, cpu + 1};
    ::setrlimit(RLIMIT_CPU, &cpu_limit);
    const rlim_t bytes = static_cast<rlim_t>(memory_gb * 1024.0 * 1024.0 * 1024.0);
    const rlimit memory_limit{bytes, bytes};
    ::setrlimit(RLIMIT_AS, &memory_limit);
    if (engine == Engine::Surfer2) {
      // Its log line per event goes to the terminal otherwise; the limits
      // above stay with it across exec.
      ::close(fds[1]);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
      ::execl(surfer2.binary.c_str(), surfer2.binary.c_str(), "--component=0", surfer2.graphml.c_str(),
              surfer2.obj.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    double engine_cpu_s = 0.0;
    ChildResult r;
    try {
      r = run_engine(in, engine, engine_cpu_s);
    } catch (const std::exception&) {  // out of memory under the limit, or an unreadable input
      std::snprintf(r.status, sizeof r.status, "budget");
    }
    [[maybe_unused]] const ssize_t a = ::write(fds[1], &r, sizeof r);
    [[maybe_unused]] const ssize_t b = ::write(fds[1], &engine_cpu_s, sizeof engine_cpu_s);
    ::_exit(0);
  }
  ::close(fds[1]);
  ChildResult r;
  double engine_cpu_s = 0.0;
  const bool reported = ::read(fds[0], &r, sizeof r) == static_cast<ssize_t>(sizeof r) &&
                        ::read(fds[0], &engine_cpu_s, sizeof engine_cpu_s) == static_cast<ssize_t>(sizeof engine_cpu_s);
  ::close(fds[0]);
  int wstatus = 0;
  rusage usage{};
  ::wait4(pid, &wstatus, 0, &usage);
  Measurement m;
  m.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  if (!reported) {  // Surfer2, or a child that died before reporting
    const bool out_of_cpu = WIFSIGNALED(wstatus) && (WTERMSIG(wstatus) == SIGXCPU || WTERMSIG(wstatus) == SIGKILL);
    const bool exited = WIFEXITED(wstatus);
    m.status = exited && WEXITSTATUS(wstatus) == 0 ? "ok" : exited ? "refused" : out_of_cpu ? "budget" : "crashed";
    m.cpu_s = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
              static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
    return m;
  }
  m.status = r.status;
  m.cpu_s = engine_cpu_s;
  return m;
}

std::vector<Input> list_inputs(const fs::path& dir) {
  std::vector<Input> inputs;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string stem = entry.path().stem().string();
    const auto underscore = stem.rfind('_');
    if (entry.path().extension() != ".json" || underscore == std::string::npos) continue;
    Input in{stem.substr(0, underscore), 0, entry.path()};
    const std::vector<PolyShape> shapes = read_polyjson_file(entry.path());
    for (const auto& loop : shapes.at(0).loops) in.n += loop.size();
    inputs.push_back(in);
  }
  std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) {
    return a.family != b.family ? a.family < b.family : a.n < b.n;
  });
  // A child starts with this process's resident pages: hand back the heap the
  // large inputs took, so each child's peak is its own.
  ::malloc_trim(0);
  return inputs;
}

// Least-squares slope of log(time) against log(n) over n >= 4096.
std::string slope(const std::vector<std::pair<std::size_t, double>>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (const auto& [n, t] : points) {
    if (n < 4096 || t <= 0.0) continue;
    const double x = std::log(static_cast<double>(n)), y = std::log(t);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++k;
  }
  if (k < 2) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", (k * sxy - sx * sy) / (k * sxx - sx * sx));
  return buf;
}

// The folder Surfer2's files pass through, removed with whatever is in it
// however run() ends: a GraphML that cannot be written throws past the loop.
struct ScratchFolder {
  fs::path path;
  ScratchFolder() = default;
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder() {
    std::error_code ec;  // nothing to report it to on the way out
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

int run(int argc, char** argv) {
  double budget_s = 120.0, memory_gb = 8.0;
  bool with_cgal = true;
  fs::path dir, surfer2;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--budget" && i + 1 < argc) budget_s = std::atof(argv[++i]);
    else if (a == "--memory-gb" && i + 1 < argc) memory_gb = std::atof(argv[++i]);
    else if (a == "--no-cgal") with_cgal = false;
    else if (a == "--surfer2" && i + 1 < argc) surfer2 = argv[++i];
    else if (!a.empty() && a[0] != '-' && dir.empty()) dir = a;
    else {  // --help, an option it does not know, or a second folder
      dir.clear();
      break;
    }
  }
  if (dir.empty()) {
    std::fprintf(stderr, "usage: procex_scale_bench [--budget SECONDS] [--memory-gb GB] [--no-cgal] "
                         "[--surfer2 SURFER] DIR\n"
                         "  DIR: the files bench/scale_inputs.py wrote\n"
                         "  SURFER: Surfer2's command-line program, as bench/surfer2_build.sh builds it\n");
    return 2;
  }
  if (!surfer2.empty() && ::access(surfer2.c_str(), X_OK) != 0) {
    std::fprintf(stderr, "procex_scale_bench: %s is not a program; build Surfer2 with bench/surfer2_build.sh\n",
                 surfer2.c_str());
    return 2;
  }
  if (std::error_code ec; !fs::is_directory(dir, ec)) {
    std::fprintf(stderr, "procex_scale_bench: %s is not a folder; give the one bench/scale_inputs.py wrote\n",
                 dir.c_str());
    return 2;
  }
  std::vector<Engine> engines{Engine::Sweep, Engine::Roof};
  if (with_cgal) engines.push_back(Engine::Cgal);
  ScratchFolder scratch;
  if (!surfer2.empty()) {
    engines.push_back(Engine::Surfer2);
    std::string folder = (fs::temp_directory_path() / "procex_scale_bench_XXXXXX").string();
    if (::mkdtemp(folder.data()) == nullptr) {
      std::fprintf(stderr, "procex_scale_bench: cannot make a scratch folder in %s\n",
                   fs::temp_directory_path().c_str());
      return 2;
    }
    scratch.path = folder;
  }

  std::printf("| family | n | engine | status | CPU s | peak MB |\n|---|---:|---|---|---:|---:|\n");
  std::map<std::pair<std::string, Engine>, std::vector<std::pair<std::size_t, double>>> times;
  std::map<std::pair<std::string, Engine>, bool> stopped;
  for (const Input& in : list_inputs(dir)) {
    for (const Engine e : engines) {
      if (stopped[{in.family, e}]) continue;
      const std::string stem = in.path.stem().string();
      const Surfer2Files files{surfer2, scratch.path / (stem + ".graphml"), scratch.path / (stem + ".obj")};
      if (e == Engine::Surfer2) {
        write_surfer2_graphml(read_footprint(in), files.graphml);
        ::malloc_trim(0);  // as in list_inputs
      }
      const Measurement m = measure(in, e, budget_s, memory_gb, files);
      if (e == Engine::Surfer2) {
        fs::remove(files.graphml);
        fs::remove(files.obj);
      }
      std::printf("| %s | %zu | %s | %s | %.3f | %.0f |\n", in.family.c_str(), in.n, engine_name(e), m.status.c_str(),
                  m.cpu_s, m.peak_mb);
      std::fflush(stdout);
      if (m.status == "ok" || m.status == "invalid") times[{in.family, e}].push_back({in.n, m.cpu_s});
      if (m.status == "budget" || m.status == "memory") stopped[{in.family, e}] = true;
    }
  }
  std::printf("\n| family | engine | log-log slope of CPU time, n >= 4096 |\n|---|---|---:|\n");
  for (const auto& [key, points] : times)
    std::printf("| %s | %s | %s |\n", key.first.c_str(), engine_name(key.second), slope(points).c_str());
  return 0;
}

}  // namespace
}  // namespace procex

// An exception that left main would end the program without unwinding run(),
// so its scratch folder would stay.
int main(int argc, char** argv) {
  try {
    return procex::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "procex_scale_bench: %s\n", e.what());
    return 1;
  }
}
