#include "io/write/destination_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "core/base/errors.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

// True while `fd` is the file at `path`: its holder removes the lock file before releasing it,
// so a run that got the lock of a removed file must take the new one.
bool still_there(int fd, const std::filesystem::path& path) {
  struct stat held {
  }, named{};
  return fstat(fd, &held) == 0 && stat(path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
         held.st_ino == named.st_ino;
}

// Takes the lock file's exclusive lock for this process; returns its descriptor.
int lock_file(const std::filesystem::path& path, const std::filesystem::path& destination,
              const std::function<void()>& waiting, const std::function<void()>& stop) {
  bool told = false;
  for (;;) {
    // Never through a link: a planted ".NAME.lock" link would have a run as root make or lock
    // the file it points to.
    const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      const int reason = errno;
      throw Error("cannot lock '" + destination.string() + "' for writing: " +
                  (reason == ELOOP ? std::string("its lock file is a symbolic link")
                                   : std::strerror(reason)) +
                  " ('" + path.string() + "'; it may be removed when no run is writing there)");
    }
    while (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      if (!told && waiting) waiting();
      told = true;
      try {
        if (stop) stop();
      } catch (...) {
        close(fd);
        throw;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (still_there(fd, path)) return fd;
    close(fd);
  }
}

// The lock files this process holds, with their descriptors and holders.
struct HeldLock {
  int fd;
  int holders;
};
std::mutex held_mutex;
std::map<std::string, HeldLock> held;

}  // namespace

DestinationLock::DestinationLock(const std::filesystem::path& destination,
                                 const std::function<void()>& waiting,
                                 const std::function<void()>& stop)
    : path_(hidden_beside(destination, ".lock")) {
  const std::string key = std::filesystem::absolute(path_).lexically_normal().string();
  std::lock_guard<std::mutex> guard(held_mutex);
  if (auto it = held.find(key); it != held.end()) {
    ++it->second.holders;
    return;
  }
  // While this waits for another process, this process's other runs wait to take any lock: a
  // rare wait, kept simple (two threads taking one file's lock at once could not both flock it).
  held[key] = {lock_file(path_, destination, waiting, stop), 1};
}

DestinationLock::~DestinationLock() {
  const std::string key = std::filesystem::absolute(path_).lexically_normal().string();
  std::lock_guard<std::mutex> guard(held_mutex);
  const auto it = held.find(key);
  if (it == held.end() || --it->second.holders > 0) return;
  unlink(path_.c_str());
  close(it->second.fd);
  held.erase(it);
}

}  // namespace tsk::io
