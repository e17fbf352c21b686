// A Kokkos profiling hook (KOKKOS_PROFILE_LIBRARY=this.so): counts the parallel dispatches
// and deep copies of a run, per kernel name, into $KCOUNT_OUT (bench/common/runs.py:
// dispatches_per_step); with $KTIMES_OUT set it also times each kernel and deep copy
// (bench/gpu/gpu_check.py). To time a kernel alone it waits for the device before and after
// it (cuCtxSynchronize from the driver already loaded, when there is one): the run is
// slower, its shares are the kernels'.
// With $KDISPATCH_OUT set it records instead how long the host spends in each dispatch,
// without waiting for the device (bench/gpu/gpu_check.py, part fluid_step): on a GPU a
// launch returns in microseconds unless it waits, as a launch object copied to constant
// memory waits for the last kernel that used it; on a host backend the dispatch runs the
// kernel itself. Deep copies during a fluid step (below) are counted under "fluid deep_copy".
// Preloaded as well (LD_PRELOAD=this.so), it counts LAMMPS' AtomKokkos::sync and ::modified
// calls by caller, space and mask into $KSYNC_OUT: on a host backend, where every space is
// the host and no copy happens, the calls that would move atom arrays on a GPU. Those made
// during a fluid step of fix darcy/pressure/kk (from its deposit kernel to its force
// kernel) are counted again under the prefix "fluid ".
//   g++ -O2 -shared -fPIC -o kokkos_dispatches.so kokkos_dispatches.cpp -ldl
#include <cxxabi.h>
#include <dlfcn.h>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {
struct Tally {
  long calls = 0;
  double seconds = 0.0;
};
std::map<std::string, long> counts;
std::map<std::string, Tally> times;    // "for NAME", "reduce NAME", "scan NAME", "deep_copy DST <- SRC"
long nfor = 0, nreduce = 0, nscan = 0, ncopy = 0, nfence = 0;
bool timing = false;
bool dispatch_timing = false;    // KDISPATCH_OUT: the host's time in each dispatch, no waits
std::map<std::string, Tally> dispatch_times;
std::string dispatch_name;
std::chrono::steady_clock::time_point dispatch_start;
int (*device_sync)() = nullptr;    // CUresult cuCtxSynchronize(void), none on host backends
struct Open {
  std::string key;
  std::chrono::steady_clock::time_point start;
};
std::vector<Open> open_regions;    // kernels do not nest; deep copies may sit inside fences

// The driver is loaded when Kokkos starts CUDA, after this library's init: looked for at
// the first regions (a host backend never loads it)
void find_device_sync()
{
  static int tries = 0;
  if (device_sync || ++tries > 1000) return;
  if (void *cuda = dlopen("libcuda.so.1", RTLD_NOW | RTLD_NOLOAD))
    device_sync = reinterpret_cast<int (*)()>(dlsym(cuda, "cuCtxSynchronize"));
}

// a kernel that fails on the device is named here, before the next call reports it blind
void wait_for_device(const char *where, const std::string &key)
{
  find_device_sync();
  if (!device_sync) return;
  if (const int status = device_sync()) {
    fprintf(stderr, "kokkos_dispatches: the device failed (CUDA driver error %d) %s %s\n", status,
            where, key.c_str());
    fflush(stderr);
    abort();
  }
}
// a counted region (kind: for, reduce, scan, deep_copy) begins: timed only with KTIMES_OUT
uint64_t begin(const char *kind, const char *name)
{
  if (!timing) return 0;
  const std::string key = std::string(kind) + " " + name;
  wait_for_device("before", key);
  open_regions.push_back({key, std::chrono::steady_clock::now()});
  return open_regions.size() - 1;
}
void end(uint64_t id)
{
  if (!timing || id >= open_regions.size()) return;
  wait_for_device("in", open_regions[id].key);
  const auto stop = std::chrono::steady_clock::now();
  Tally &t = times[open_regions[id].key];
  ++t.calls;
  t.seconds += std::chrono::duration<double>(stop - open_regions[id].start).count();
  open_regions.resize(id);
}
}    // namespace

extern "C" void kokkosp_init_library(int, uint64_t, uint32_t, void *)
{
  timing = getenv("KTIMES_OUT") != nullptr;
  dispatch_timing = !timing && getenv("KDISPATCH_OUT") != nullptr;
}
namespace {
void begin_dispatch(const char *kind, const char *name)
{
  if (!dispatch_timing) return;
  dispatch_name = std::string(kind) + " " + name;
  dispatch_start = std::chrono::steady_clock::now();
}
void end_dispatch()
{
  if (!dispatch_timing || dispatch_name.empty()) return;
  Tally &t = dispatch_times[dispatch_name];
  ++t.calls;
  t.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - dispatch_start).count();
  dispatch_name.clear();
}
}    // namespace
namespace {
std::map<std::string, long> atom_calls;    // "[fluid ]sync|modified SPACE MASK CALLER"
bool in_fluid_step = false;    // between darcy/pressure's deposit and force kernels

// the function that called from `address` (demangled, its arguments dropped)
std::string caller_of(void *address)
{
  Dl_info info;
  if (!dladdr(address, &info) || !info.dli_sname) return "?";
  int status = 0;
  char *name = abi::__cxa_demangle(info.dli_sname, nullptr, nullptr, &status);
  std::string text = status == 0 && name ? name : info.dli_sname;
  free(name);
  return text.substr(0, text.find('('));
}

void count_atom_call(const char *what, int space, unsigned mask, void *caller)
{
  static const char *spaces[] = {"Host", "Device"};
  char head[64];
  snprintf(head, sizeof(head), "%s %s 0x%x ", what, space == 0 || space == 1 ? spaces[space] : "?", mask);
  const std::string key = head + caller_of(caller);
  ++atom_calls[key];
  if (in_fluid_step) ++atom_calls["fluid " + key];
}
}    // namespace

// LAMMPS_NS::AtomKokkos::sync(ExecutionSpace, unsigned) and ::modified, forwarded
extern "C" void _ZN9LAMMPS_NS10AtomKokkos4syncENS_14ExecutionSpaceEj(void *self, int space, unsigned mask)
{
  static auto next = reinterpret_cast<void (*)(void *, int, unsigned)>(
      dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS10AtomKokkos4syncENS_14ExecutionSpaceEj"));
  count_atom_call("sync", space, mask, __builtin_return_address(0));
  next(self, space, mask);
}
extern "C" void _ZN9LAMMPS_NS10AtomKokkos8modifiedENS_14ExecutionSpaceEj(void *self, int space, unsigned mask)
{
  static auto next = reinterpret_cast<void (*)(void *, int, unsigned)>(
      dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS10AtomKokkos8modifiedENS_14ExecutionSpaceEj"));
  count_atom_call("modified", space, mask, __builtin_return_address(0));
  next(self, space, mask);
}

extern "C" void kokkosp_finalize_library()
{
  if (getenv("KSYNC_OUT") && !atom_calls.empty()) {
    FILE *a = fopen(getenv("KSYNC_OUT"), "w");
    for (auto &kv : atom_calls) fprintf(a, "%ld %s\n", kv.second, kv.first.c_str());
    fclose(a);
  }
  FILE *f = fopen(getenv("KCOUNT_OUT") ? getenv("KCOUNT_OUT") : "kcount.txt", "w");
  fprintf(f, "for %ld reduce %ld scan %ld deep_copy %ld fence %ld\n", nfor, nreduce, nscan, ncopy, nfence);
  for (auto &kv : counts) fprintf(f, "%ld %s\n", kv.second, kv.first.c_str());
  fclose(f);
  if (dispatch_timing) {
    FILE *d = fopen(getenv("KDISPATCH_OUT"), "w");
    fprintf(d, "# seconds calls kind name (the host's time in the dispatch call, no waits)\n");
    for (auto &kv : dispatch_times) fprintf(d, "%.6f %ld %s\n", kv.second.seconds, kv.second.calls, kv.first.c_str());
    fclose(d);
  }
  if (!timing) return;
  FILE *t = fopen(getenv("KTIMES_OUT"), "w");
  fprintf(t, "# seconds calls kind name (waited for the device: %s)\n", device_sync ? "yes" : "no");
  for (auto &kv : times) fprintf(t, "%.6f %ld %s\n", kv.second.seconds, kv.second.calls, kv.first.c_str());
  fclose(t);
}
extern "C" void kokkosp_begin_parallel_for(const char *n, uint32_t, uint64_t *k)
{
  const std::string name = n;
  if (name == "darcy/pressure:deposit") in_fluid_step = true;
  if (name == "darcy/pressure:force") in_fluid_step = false;
  ++nfor;
  ++counts[n];
  begin_dispatch("for", n);
  *k = begin("for", n);
}
extern "C" void kokkosp_end_parallel_for(uint64_t k)
{
  end(k);
  end_dispatch();
}
extern "C" void kokkosp_begin_parallel_reduce(const char *n, uint32_t, uint64_t *k)
{
  ++nreduce;
  ++counts[n];
  begin_dispatch("reduce", n);
  *k = begin("reduce", n);
}
extern "C" void kokkosp_end_parallel_reduce(uint64_t k)
{
  end(k);
  end_dispatch();
}
extern "C" void kokkosp_begin_parallel_scan(const char *n, uint32_t, uint64_t *k)
{
  ++nscan;
  ++counts[n];
  *k = begin("scan", n);
}
extern "C" void kokkosp_end_parallel_scan(uint64_t k) { end(k); }
extern "C" void kokkosp_begin_fence(const char *, uint32_t, uint64_t *k)
{
  ++nfence;
  *k = 0;
}
extern "C" void kokkosp_end_fence(uint64_t) {}
namespace {
uint64_t copy_region = UINT64_MAX;
}
// Kokkos_Profiling_SpaceHandle: the memory space's name, passed by value
struct SpaceHandle {
  char name[64];
};
extern "C" void kokkosp_begin_deep_copy(SpaceHandle, const char *dst, const void *, SpaceHandle,
                                        const char *src, const void *, uint64_t)
{
  ++ncopy;
  if (in_fluid_step) ++counts[std::string("fluid deep_copy ") + dst + " <- " + src];
  copy_region = timing ? begin("deep_copy", (std::string(dst) + " <- " + src).c_str()) : UINT64_MAX;
}
extern "C" void kokkosp_end_deep_copy()
{
  if (copy_region != UINT64_MAX) end(copy_region);
  copy_region = UINT64_MAX;
}
