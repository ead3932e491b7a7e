#include "output_files.h"

#include <unistd.h>

#include <system_error>
#include <vector>

#include "errors.h"

namespace tsk::io {

namespace fs = std::filesystem;

namespace {

// The folder `destination` goes in, after checking that it names a file in a folder that exists
// and can be written.
fs::path output_folder(const fs::path& destination) {
  if (destination.filename().empty())
    throw Error("output path '" + destination.string() + "' names no file");
  const fs::path folder = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw Error("cannot write '" + destination.string() + "': folder '" + folder.string() +
                "' does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw Error("cannot write '" + destination.string() + "': folder '" + folder.string() +
                "' is not writable");
  }
  // The output replaces what is there: only ever a file (a folder, a device or a pipe would be
  // destroyed, or refuse at the very end).
  const fs::file_status existing = fs::status(destination, ec);
  if (fs::exists(existing) && !fs::is_regular_file(existing)) {
    throw Error("'" + destination.string() +
                "' exists and is not a file (a folder, a device or a pipe); choose another name");
  }
  return folder;
}

}  // namespace

void check_output_path(const fs::path& destination) {
  output_folder(destination);
}

void write_atomically(const fs::path& destination,
                      const std::function<void(const fs::path&)>& write) {
  const fs::path folder = output_folder(destination);
  std::error_code ec;
  // Named after the output, shortened so that a name near the 255-byte limit still fits.
  constexpr std::size_t kNameBytes = 200;
  const fs::path staging = folder / ("." + destination.filename().string().substr(0, kNameBytes) +
                                     ".partial-" + std::to_string(getpid()));
  fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec)) {
    throw Error("cannot write in folder '" + folder.string() + "': " + ec.message());
  }
  try {
    write(staging / destination.filename());
    std::vector<fs::path> made;
    for (const auto& entry : fs::directory_iterator(staging)) made.push_back(entry.path());
    for (const auto& file : made) {
      fs::rename(file, folder / file.filename());
    }
    fs::remove(staging);
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    throw Error("cannot write '" + destination.string() + "': " + e.code().message());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
}

}  // namespace tsk::io
