// The memory limit of the control group a process runs in (a container's, a batch scheduler's,
// a systemd slice's), which the machine's physical memory does not show: a run that plans for
// the machine's memory there is killed when it passes the limit, with no message of ours.
#pragma once

#include <string>

namespace tsk {

// The least memory limit, in bytes, on the path from the process's control group up to the root,
// in cgroup v2 (memory.max) and v1 (the memory controller's memory.limit_in_bytes). `membership`
// is the text of /proc/self/cgroup and `mount` where the hierarchies are mounted
// (/sys/fs/cgroup). Infinity when no limit is set or none can be read ("max", files missing).
double cgroup_memory_limit(const std::string& membership, const std::string& mount);

// cgroup_memory_limit of this process, read once.
double this_process_memory_limit();

}  // namespace tsk
