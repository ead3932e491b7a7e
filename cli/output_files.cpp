#include "output_files.h"

#include <unistd.h>

#include <system_error>
#include <vector>

#include "errors.h"

namespace tsk::io {

namespace fs = std::filesystem;

void write_atomically(const fs::path& destination,
                      const std::function<void(const fs::path&)>& write) {
  if (destination.filename().empty())
    throw Error("output path '" + destination.string() + "' names no file");
  const fs::path folder = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw Error("cannot write '" + destination.string() + "': folder '" + folder.string() +
                "' does not exist");
  }
  const fs::path staging =
      folder / ("." + destination.filename().string() + ".partial-" + std::to_string(getpid()));
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
