#include "common/blas_threads.hpp"

#include <dlfcn.h>

namespace coremodal {
namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

SetThreads set_threads() { return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
GetThreads get_threads() { return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }

}  // namespace

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
