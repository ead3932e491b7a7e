#include "io/write/checked_writes.h"

#include <cpl_vsi.h>

#include <cerrno>
#include <map>
#include <mutex>
#include <system_error>

namespace tsk::io {
namespace {

constexpr char kPrefix[] = "/vsitsk_checked/";

// The failures recorded, by the real path of their file; files may be written from any thread.
std::mutex failures_mutex;
std::map<std::string, std::string> failures;

void record_failure(const std::string& real, int error) {
  const std::string why =
      error ? std::error_code(error, std::generic_category()).message() : "a write failed";
  const std::lock_guard<std::mutex> lock(failures_mutex);
  failures.emplace(real, why);  // the first failure of a file says the most
}

struct CheckedFile {
  VSILFILE* file;
  std::string real;
};

CheckedFile& as_file(void* handle) {
  return *static_cast<CheckedFile*>(handle);
}

// A result of 0 is success for the calls below but write.
int checked(CheckedFile& f, int result) {
  if (result != 0) record_failure(f.real, errno);
  return result;
}

// Every call passed on to the file itself; GDAL hands the callbacks the names without the prefix.
VSIFilesystemPluginCallbacksStruct* callbacks() {
  VSIFilesystemPluginCallbacksStruct* c = VSIAllocFilesystemPluginCallbacksStruct();
  c->stat = [](void*, const char* name, VSIStatBufL* buf, int flags) {
    return VSIStatExL(name, buf, flags);
  };
  c->unlink = [](void*, const char* name) { return VSIUnlink(name); };
  c->rename = [](void*, const char* from, const char* to) { return VSIRename(from, to); };
  c->mkdir = [](void*, const char* name, long mode) { return VSIMkdir(name, mode); };
  c->rmdir = [](void*, const char* name) { return VSIRmdir(name); };
  c->read_dir = [](void*, const char* name, int most) { return VSIReadDirEx(name, most); };
  c->open = [](void*, const char* name, const char* access) -> void* {
    VSILFILE* file = VSIFOpenExL(name, access, TRUE);
    return file ? new CheckedFile{file, name} : nullptr;
  };
  c->tell = [](void* h) { return VSIFTellL(as_file(h).file); };
  c->seek = [](void* h, vsi_l_offset offset, int whence) {
    return VSIFSeekL(as_file(h).file, offset, whence);
  };
  c->read = [](void* h, void* buffer, std::size_t size, std::size_t count) {
    return VSIFReadL(buffer, size, count, as_file(h).file);
  };
  c->eof = [](void* h) { return VSIFEofL(as_file(h).file); };
  c->write = [](void* h, const void* buffer, std::size_t size, std::size_t count) {
    CheckedFile& f = as_file(h);
    errno = 0;
    const std::size_t written = VSIFWriteL(buffer, size, count, f.file);
    if (written < count) record_failure(f.real, errno);
    return written;
  };
  c->flush = [](void* h) { return checked(as_file(h), VSIFFlushL(as_file(h).file)); };
  c->truncate = [](void* h, vsi_l_offset size) {
    return checked(as_file(h), VSIFTruncateL(as_file(h).file, size));
  };
  c->close = [](void* h) {
    CheckedFile* f = &as_file(h);
    const int result = checked(*f, VSIFCloseL(f->file));  // a close flushes what is buffered
    delete f;
    return result;
  };
  return c;
}

}  // namespace

std::string checked_path(const std::filesystem::path& real) {
  static const bool installed = [] {
    VSIFilesystemPluginCallbacksStruct* c = callbacks();
    const bool ok = VSIInstallPluginHandler(kPrefix, c) == 0;
    VSIFreeFilesystemPluginCallbacksStruct(c);
    return ok;
  }();
  return installed ? kPrefix + real.string() : real.string();
}

std::string take_write_failure(const std::filesystem::path& folder) {
  const std::string prefix = (folder / "").string();
  const std::lock_guard<std::mutex> lock(failures_mutex);
  std::string why;
  for (auto it = failures.begin(); it != failures.end();) {
    if (it->first.rfind(prefix, 0) == 0) {
      if (why.empty()) why = it->second;
      it = failures.erase(it);
    } else {
      ++it;
    }
  }
  return why;
}

}  // namespace tsk::io
