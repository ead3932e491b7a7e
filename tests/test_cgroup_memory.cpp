// A run plans for the memory limit of its control group when that is below the machine's
// (a container's): the limit read from made-up cgroup v1, v2 and hybrid trees.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "catch_compat.h"
#include "core/base/cgroup_memory.h"

using tsk::cgroup_memory_limit;
namespace fs = std::filesystem;

namespace {

// A made-up /sys/fs/cgroup, removed after the test.
struct CgroupTree {
  CgroupTree() : mount(fs::temp_directory_path() / ("tsk-cgroup-" + std::to_string(getpid()))) {
    fs::remove_all(mount);
  }
  ~CgroupTree() { fs::remove_all(mount); }
  // Writes `text` to the control file `file` of `group` (a path under the mount).
  void set(const std::string& group, const std::string& file, const std::string& text) const {
    const fs::path dir = mount / fs::path(group).relative_path();
    fs::create_directories(dir);
    std::ofstream(dir / file) << text << "\n";
  }
  double limit(const std::string& membership) const {
    return cgroup_memory_limit(membership, mount.string());
  }
  fs::path mount;
};

constexpr double kGiB = 1024.0 * 1024 * 1024;

}  // namespace

TEST_CASE("cgroup v2: the least memory.max from the process's group up", "[memory]") {
  CgroupTree tree;
  tree.set("/", "memory.max", "max");
  tree.set("/pod", "memory.max", "2147483648");
  tree.set("/pod/worker", "memory.max", "max");
  CHECK(tree.limit("0::/pod/worker\n") == 2 * kGiB);  // an ancestor's limit holds
  tree.set("/pod/worker", "memory.max", "536870912");
  CHECK(tree.limit("0::/pod/worker\n") == 0.5 * kGiB);  // the tighter of the two
  CHECK(tree.limit("0::/pod\n") == 2 * kGiB);           // a child's limit does not
  CHECK(std::isinf(tree.limit("0::/\n")));              // "max" is none
}

TEST_CASE("cgroup v1 and hybrid trees: the memory controller's limit", "[memory]") {
  CgroupTree tree;
  // v1, the memory controller on a line of its own or with others.
  tree.set("/memory/jobs", "memory.limit_in_bytes", "3000000000");
  tree.set("/memory/jobs/42", "memory.limit_in_bytes", "9223372036854771712");
  CHECK(tree.limit("4:memory:/jobs/42\n0::/\n") == 3e9);
  CHECK(tree.limit("7:cpu,memory:/jobs/42\n") == 3e9);
  CHECK(std::isinf(tree.limit("5:cpu,cpuacct:/jobs/42\n")));  // another controller's group
  // Hybrid: cgroup v2 mounted under unified/.
  tree.set("/unified/slice", "memory.max", "1073741824");
  CHECK(tree.limit("4:memory:/\n0::/slice\n") == kGiB);
}

TEST_CASE("no memory limit where none can be read", "[memory]") {
  CgroupTree tree;
  CHECK(std::isinf(tree.limit("")));
  CHECK(std::isinf(tree.limit("0::/nowhere\n")));  // no such files
  tree.set("/odd", "memory.max", "lots");
  CHECK(std::isinf(tree.limit("0::/odd\n")));
  tree.set("/zero", "memory.max", "0");
  CHECK(std::isinf(tree.limit("0::/zero\n")));  // not a limit to plan for
  tree.set("/", "memory.max", "1073741824");
  CHECK(std::isinf(tree.limit("0::/../../etc\n")));  // not a path to follow
  CHECK(std::isinf(tree.limit("garbage without colons\n")));
  CHECK(tree.limit("0::/odd\n") == kGiB);  // the root's limit above it
}
