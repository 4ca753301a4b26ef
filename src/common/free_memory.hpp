// The memory a run may still take. MemAvailable (/proc/meminfo) is the
// machine's; inside a container or a batch job's allocation (a control
// group with a memory limit) the process is killed at the group's limit
// long before the machine runs short, so the group's headroom counts too.
#pragma once

#include <optional>
#include <string>

namespace coremodal {

// MB the run may still take: the least of MemAvailable and the control
// group's headroom (cgroup v2 memory.max - memory.current, or v1
// memory.limit_in_bytes - memory.usage_in_bytes); 0 when neither is
// readable.
double free_memory_mb();

// A control group's headroom in MB from its two files' text (limit, then
// usage, in bytes); none when the limit is "max" (unlimited) or unreadable.
std::optional<double> cgroup_headroom_mb(const std::string& limit, const std::string& usage);

}  // namespace coremodal
