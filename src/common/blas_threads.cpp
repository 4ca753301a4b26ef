#include "common/blas_threads.hpp"

#include "common/free_memory.hpp"  // kBytesPerMb

#include <dlfcn.h>
#include <fcntl.h>
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace coremodal {
namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

SetThreads set_threads() { return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
GetThreads get_threads() { return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }

// The address space one more OpenBLAS thread takes as it starts: its buffer
// (BUFFER_SIZE, 128 MB on x86-64: the 134217728-byte mmap strace shows), the
// malloc arena glibc reserves for a thread's first allocation (HEAP_MAX_SIZE,
// 64 MB on 64-bit) and its stack (8 MB, the default RLIMIT_STACK). Measured
// without a limit: VmSize at the first check 374 MB on one thread, 510 MB on
// two (the arena then shared); the arena counts where it is not.
constexpr double kPerThreadMb = 128 + 64 + 8;

// Set in the program's environment when it was executed again with fewer
// threads: "<threads OpenBLAS would start> <threads given> <limit in MB>".
// Also what keeps it from being executed again a second time.
constexpr const char kLoweredName[] = "COREMODAL_BLAS_THREADS_LOWERED";

// The value of `name` in `envp`, or null; the C library's getenv() does not
// see the environment yet in the preinit array.
const char* find_variable(char** envp, const char* name) {
    const size_t length = std::strlen(name);
    for (char** e = envp; e && *e; ++e)
        if (std::strncmp(*e, name, length) == 0 && (*e)[length] == '=') return *e + length + 1;
    return nullptr;
}

// What this process has mapped (VmSize) in MB, from /proc/self/statm's first
// field (pages), read without the C++ library; 0 when unreadable.
double mapped_mb() {
    const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    char text[64] = {};
    const ssize_t n = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    return n > 0 ? std::strtod(text, nullptr) * double(::sysconf(_SC_PAGESIZE)) / kBytesPerMb : 0;
}

// The threads OpenBLAS will start: the first positive of the variables it
// reads (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS, OMP_NUM_THREADS; OpenBLAS
// 0.3, driver/others/openblas_env.c), and at most (or without them) the CPUs
// this process may run on.
int threads_openblas_starts(char** envp) {
    cpu_set_t cpus;
    CPU_ZERO(&cpus);
    const int available = ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus) : 1;
    for (const char* name : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
        if (const char* value = find_variable(envp, name); value && std::atoi(value) > 0)
            return std::min(std::atoi(value), available);
    return available;
}

}  // namespace

void fit_blas_threads_to_address_space(char** argv, char** envp, double least_headroom_mb) {
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
    if (find_variable(envp, kLoweredName)) return;  // executed again already
    const double limit_mb = double(limit.rlim_cur) / kBytesPerMb;
    const int wanted = threads_openblas_starts(envp);
    const double room_mb = limit_mb - mapped_mb() - least_headroom_mb;
    const int affordable = 1 + (room_mb > 0 ? int(room_mb / kPerThreadMb) : 0);
    if (affordable >= wanted) return;

    // The environment without OPENBLAS_NUM_THREADS, then the lowered count
    // and the note's numbers. Static: nothing to free, execve replaces it all.
    static char threads[48], lowered[96];
    std::snprintf(threads, sizeof threads, "OPENBLAS_NUM_THREADS=%d", affordable);
    std::snprintf(lowered, sizeof lowered, "%s=%d %d %ld", kLoweredName, wanted, affordable, long(limit_mb + 0.5));
    size_t count = 0;
    while (envp && envp[count]) ++count;
    char** env = static_cast<char**>(std::calloc(count + 3, sizeof(char*)));
    if (!env) return;
    size_t kept = 0;
    for (size_t i = 0; i < count; ++i)
        if (std::strncmp(envp[i], "OPENBLAS_NUM_THREADS=", std::strlen("OPENBLAS_NUM_THREADS=")) != 0)
            env[kept++] = envp[i];
    env[kept++] = threads;
    env[kept++] = lowered;
    ::execve("/proc/self/exe", argv, env);
    std::free(env);  // not executed (no /proc): go on with OpenBLAS's own count
}

std::string blas_threads_note() {
    const char* lowered = std::getenv(kLoweredName);
    int wanted = 0, given = 0;
    long limit_mb = 0;
    if (!lowered || std::sscanf(lowered, "%d %d %ld", &wanted, &given, &limit_mb) != 3) return "";
    return "BLAS on " + std::to_string(given) + (given == 1 ? " thread" : " threads") + " instead of " +
           std::to_string(wanted) + ": the address-space limit (ulimit -v) of " + std::to_string(limit_mb) +
           " MB leaves no room for more (each OpenBLAS thread takes up to " + std::to_string(int(kPerThreadMb)) +
           " MB as it starts)";
}

SingleThreadBlas::SingleThreadBlas() {
    const SetThreads set = set_threads();
    const GetThreads get = get_threads();
    if (!set || !get) return;
    previous_ = get();
    if (previous_ > 1) set(1);
    else previous_ = 0;
}

SingleThreadBlas::~SingleThreadBlas() {
    if (previous_ > 1) set_threads()(previous_);
}

}  // namespace coremodal
