#include "io/write/output_files.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <system_error>
#include <vector>

#include "core/base/errors.h"
#include "io/read/gdal_util.h"
#include "io/write/output_set.h"

namespace tsk::io {

namespace fs = std::filesystem;

fs::path check_output_path(const fs::path& destination) {
  if (destination.filename().empty())
    throw Error("output path '" + destination.string() + "' names no file");
  const fs::path folder = folder_of(destination);
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
  // A member of another dataset (a shapefile's .dbf): writing it would replace that dataset's
  // files too.
  if (fs::exists(existing)) {
    const std::string main = main_file_of_other_dataset(destination.string());
    if (!main.empty()) {
      throw Error("'" + destination.string() + "' is part of the dataset '" + main +
                  "', whose files writing it would replace; choose another name");
    }
  }
  return folder;
}

void write_atomically(const fs::path& destination,
                      const std::function<void(const fs::path&)>& write) {
  // With no set open on this thread, the output is a set of its own (with what it writes inside).
  std::optional<OutputSet> own;
  OutputSet* set = OutputSet::current();
  if (!set) set = &own.emplace();
  const fs::path staged = set->stage(destination);
  try {
    write(staged);
  } catch (...) {
    set->discard(destination);
    throw;
  }
  if (own) own->commit();
}

fs::path folder_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

std::string lowercase_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

fs::path hidden_beside(const fs::path& destination, const std::string& ending) {
  constexpr std::size_t kNameBytes = 200;
  return folder_of(destination) /
         ("." + destination.filename().string().substr(0, kNameBytes) + ending);
}

void write_text_file(const fs::path& destination, const std::string& text) {
  write_atomically(destination, [&](const fs::path& staged) {
    FILE* file = std::fopen(staged.c_str(), "wb");
    if (!file) throw Error("cannot write '" + destination.string() + "': " + std::strerror(errno));
    const bool all = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    int reason = all ? 0 : errno;
    if (std::fclose(file) != 0 && reason == 0) reason = errno;
    if (!all || reason != 0) {
      throw Error("cannot write '" + destination.string() +
                  "': " + std::strerror(reason != 0 ? reason : EIO));
    }
  });
}

}  // namespace tsk::io
