#include "io/write/early_writeback.h"

#include <fcntl.h>
#include <unistd.h>

namespace tsk::io {

EarlyWriteback::EarlyWriteback(const std::string& path) {
#if defined(__linux__)
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
#else
  (void)path;
#endif
}

EarlyWriteback::~EarlyWriteback() {
  if (fd_ >= 0) ::close(fd_);
}

bool EarlyWriteback::start() noexcept {
#if defined(__linux__)
  // Offset 0 and length 0: the whole file, as far as it reaches now.
  return fd_ >= 0 && ::sync_file_range(fd_, 0, 0, SYNC_FILE_RANGE_WRITE) == 0;
#else
  return false;
#endif
}

}  // namespace tsk::io
