// An exclusive lock on an output's destination between processes: runs of either front end
// (the command line, qgis_process, QGIS instances) writing one output put their files in place one
// after the other, never interleaved, and a run that fails removes only what it made itself.
// Within one process the lock of a destination is shared (a QGIS run may write two outputs into
// one GeoPackage): it is released when its last holder goes.
#pragma once

#include <filesystem>
#include <functional>

namespace tsk::io {

class DestinationLock {
 public:
  // Takes the lock of `destination` (a hidden lock file beside it), waiting while another run
  // holds it; `waiting` is called once when it must wait, `stop` (if given) every 100 ms while it
  // does, and throws to give up. Throws Error when the lock file cannot be made.
  explicit DestinationLock(const std::filesystem::path& destination,
                           const std::function<void()>& waiting = {},
                           const std::function<void()>& stop = {});
  ~DestinationLock();  // removes the lock file and releases the lock
  DestinationLock(const DestinationLock&) = delete;
  DestinationLock& operator=(const DestinationLock&) = delete;

 private:
  std::filesystem::path path_;  // of the lock file
};

}  // namespace tsk::io
