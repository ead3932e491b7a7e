#include "io/write/output_files.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include "core/base/errors.h"
#include "io/read/gdal_util.h"
#include "io/write/destination_lock.h"

namespace tsk::io {

namespace fs = std::filesystem;

namespace {

// A staging folder is named ".NAME.partial-PID" and holds this marker from its making on: only a
// folder with the marker is ever removed as a staging folder (a user's ".photos.partial-88888"
// is not ours).
constexpr char kStagingMark[] = ".partial-";
constexpr char kStagingMarker[] = ".terrain-sketch-staging";

// True when `folder` is a staging folder a run of this tool made: a real folder (not a link to
// one) holding the marker.
bool made_by_a_run(const fs::path& folder) {
  std::error_code ec;
  return fs::is_directory(fs::symlink_status(folder, ec)) &&
         fs::is_regular_file(fs::symlink_status(folder / kStagingMarker, ec));
}

// The folder `destination` goes in, after checking that it names a file in a folder that exists
// and can be written.
fs::path output_folder(const fs::path& destination) {
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

// Removes the staging folders (".NAME.partial-PID") in `folder` of runs that no longer live,
// whatever output they were for: a run killed outright (kill -9, a power cut) leaves its partial
// output there, as big as it had got.
void remove_stale_staging(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const std::size_t mark = name.rfind(kStagingMark);
    if (name.empty() || name[0] != '.' || mark == std::string::npos || !made_by_a_run(entry.path()))
      continue;
    const std::string pid = name.substr(mark + std::strlen(kStagingMark));
    if (pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    // Gone, not merely another user's (EPERM).
    if (kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) {
      stale.push_back(entry.path());
    }
  }
  for (const fs::path& path : stale) fs::remove_all(path, ec);
}

// Removes the files of the earlier output at `destination` that the new set `made` does not
// replace: those GDAL lists for it and, for a shapefile, the side files GDAL, QGIS and ArcGIS
// keep beside it (a stale spatial index .qix hides every feature from a filtered read). Only
// files in the destination's folder named after it go: never a VRT's sources elsewhere.
void remove_earlier_output(const fs::path& destination, const std::vector<fs::path>& made) {
  std::error_code ec;
  if (!fs::is_regular_file(destination, ec)) return;
  const fs::path folder = folder_of(destination);
  const std::string stem = destination.stem().string(), name = destination.filename().string();
  std::vector<fs::path> files;
  for (const std::string& file : dataset_files(destination.string())) files.emplace_back(file);
  files.push_back(folder / (name + ".aux.xml"));
  if (destination.extension() == ".shp") {
    for (const char* ext : {".shx", ".dbf", ".prj", ".cpg", ".qix", ".sbn", ".sbx", ".qmd"})
      files.push_back(folder / (stem + ext));
    files.push_back(folder / (name + ".xml"));
  }
  for (const fs::path& file : files) {
    const std::string file_name = file.filename().string();
    const bool ours = fs::equivalent(folder_of(file), folder, ec) && file_name.rfind(stem, 0) == 0;
    const bool replaced = std::any_of(made.begin(), made.end(),
                                      [&](const fs::path& m) { return m.filename() == file_name; });
    if (ours && !replaced) fs::remove(file, ec);
  }
}

// Makes this run's staging folder for `destination`, marked as made by a run; one of this process
// left by an earlier output of the same name is removed first, a folder that is not ours refused.
fs::path make_staging(const fs::path& destination, const fs::path& folder) {
  const fs::path staging = hidden_beside(destination, kStagingMark + std::to_string(getpid()));
  std::error_code ec;
  if (made_by_a_run(staging)) fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec)) {
    throw Error("cannot write in folder '" + folder.string() + "': " +
                (ec ? ec.message()
                    : "'" + staging.filename().string() +
                          "' is there and was not made by this tool; move it"));
  }
  std::ofstream marker(staging / kStagingMarker);
  if (!marker) {
    fs::remove(staging, ec);
    throw Error("cannot write in folder '" + folder.string() + "'");
  }
  return staging;
}

}  // namespace

void check_output_path(const fs::path& destination) {
  output_folder(destination);
}

void write_atomically(const fs::path& destination,
                      const std::function<void(const fs::path&)>& write) {
  const fs::path folder = output_folder(destination);
  std::error_code ec;
  remove_stale_staging(folder);
  const fs::path staging = make_staging(destination, folder);
  try {
    write(staging / destination.filename());
    std::vector<fs::path> made;
    for (const auto& entry : fs::directory_iterator(staging))
      if (entry.path().filename() != kStagingMarker) made.push_back(entry.path());
    {
      // One run at a time puts its set in place, the earlier output's files all gone.
      const DestinationLock lock(destination);
      remove_earlier_output(destination, made);
      for (const auto& file : made) fs::rename(file, folder / file.filename());
    }
    fs::remove(staging / kStagingMarker);
    fs::remove(staging);
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    throw Error("cannot write '" + destination.string() + "': " + e.code().message());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
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
