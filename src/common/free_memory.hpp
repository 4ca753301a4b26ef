// The memory a run may still take. MemAvailable (/proc/meminfo) is the
// machine's; inside a container or a batch job's allocation (a control
// group with a memory limit) the process is killed at the group's limit
// long before the machine runs short, so the group's headroom counts too;
// under an address-space limit (`ulimit -v`, RLIMIT_AS) an allocation fails
// at the limit, so the room left under it counts as well.
#pragma once

#include <optional>
#include <string>

namespace coremodal {

// Bytes in the MB (MiB) every memory figure here is given in.
inline constexpr double kBytesPerMb = 1024.0 * 1024.0;

// MB the run may still take: the least of MemAvailable, the control
// group's headroom (cgroup v2 memory.max - memory.current, or v1
// memory.limit_in_bytes - memory.usage_in_bytes) and the address space left
// under RLIMIT_AS; 0 when none is known.
double free_memory_mb();

// The address-space limit (RLIMIT_AS) in MB and what this process has
// mapped (VmSize) in MB; none when there is no limit.
struct AddressSpace {
    double limit_mb = 0, used_mb = 0;
    double headroom_mb() const { return limit_mb > used_mb ? limit_mb - used_mb : 0.0; }
};
std::optional<AddressSpace> address_space_limit();

// What a run that ran out of memory tells its user: what it needed (the
// estimate, when known: `needed_mb` > 0) against what it had (the
// address-space limit, the machine's and control group's free memory, the
// peak it reached), and what to do: more memory, or a smaller problem.
// `estimate_of` says where the need comes from.
std::string out_of_memory_text(double needed_mb = 0, const std::string& estimate_of = "the solver's estimate");

// A control group's headroom in MB from its two files' text (limit, then
// usage, in bytes); none when the limit is "max" (unlimited) or unreadable.
std::optional<double> cgroup_headroom_mb(const std::string& limit, const std::string& usage);

}  // namespace coremodal
