#include "io/write/output_set.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>

#include "core/base/errors.h"
#include "io/read/gdal_util.h"
#include "io/write/destination_lock.h"
#include "io/write/output_files.h"

namespace tsk::io {

namespace fs = std::filesystem;

namespace {

// A staging folder is named ".NAME.partial-PID-N" and holds this marker from its making on: only a
// folder with the marker is ever removed as a staging folder (a user's ".photos.partial-88888"
// is not ours).
constexpr char kStagingMark[] = ".partial-";
constexpr char kStagingMarker[] = ".terrain-sketch-staging";

thread_local OutputSet* open_set = nullptr;

// True when `folder` is a staging folder a run of this tool made: a real folder (not a link to
// one) holding the marker.
bool made_by_a_run(const fs::path& folder) {
  std::error_code ec;
  return fs::is_directory(fs::symlink_status(folder, ec)) &&
         fs::is_regular_file(fs::symlink_status(folder / kStagingMarker, ec));
}

// The process that made a staging folder named `name`, or -1 when the name is not of one.
long staging_pid(const std::string& name) {
  const std::size_t mark = name.rfind(kStagingMark);
  if (name.empty() || name[0] != '.' || mark == std::string::npos) return -1;
  const std::string rest = name.substr(mark + std::strlen(kStagingMark));
  const std::string pid = rest.substr(0, rest.find('-'));
  if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos)
    return -1;
  return std::stol(pid);
}

// Removes the staging folders in `folder` of runs that no longer live, whatever output they were
// for: a run killed outright (kill -9, a power cut) leaves its partial output there, as big as it
// had got.
void remove_stale_staging(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const long pid = staging_pid(entry.path().filename().string());
    // Gone, not merely another user's (EPERM).
    if (pid > 0 && made_by_a_run(entry.path()) && kill(static_cast<pid_t>(pid), 0) != 0 &&
        errno == ESRCH) {
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

// Makes a fresh staging folder for `destination`, marked as made by a run; a folder of that name
// that is not ours is refused. Named after the process and a count, so that two runs of one
// process (QGIS) never share one.
fs::path make_staging(const fs::path& destination, const fs::path& folder) {
  static std::atomic<unsigned> made{0};
  const fs::path staging = hidden_beside(destination, kStagingMark + std::to_string(getpid()) +
                                                          "-" + std::to_string(made.fetch_add(1)));
  std::error_code ec;
  if (made_by_a_run(staging)) fs::remove_all(staging, ec);  // of a dead process with this pid
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

// The files a run wrote in `staging`, but the marker.
std::vector<fs::path> files_made(const fs::path& staging) {
  std::vector<fs::path> made;
  for (const auto& entry : fs::directory_iterator(staging))
    if (entry.path().filename() != kStagingMarker) made.push_back(entry.path());
  return made;
}

std::string key_of(const fs::path& destination) {
  return fs::absolute(destination).lexically_normal().string();
}

}  // namespace

OutputSet::OutputSet(Waiting waiting) : waiting_(std::move(waiting)), outer_(open_set) {
  open_set = this;
}

OutputSet::~OutputSet() {
  std::error_code ec;
  for (const Staged& s : staged_) fs::remove_all(s.folder, ec);
  open_set = outer_;
}

OutputSet* OutputSet::current() {
  return open_set;
}

fs::path OutputSet::stage(const fs::path& destination) {
  const fs::path folder = check_output_path(destination);
  for (const Staged& s : staged_) {
    if (key_of(s.destination) == key_of(destination))
      throw Error("two outputs of the run are named '" + destination.string() + "'");
  }
  remove_stale_staging(folder);
  staged_.push_back({destination, make_staging(destination, folder)});
  return staged_.back().folder / destination.filename();
}

void OutputSet::discard(const fs::path& destination) noexcept {
  const auto it = std::find_if(staged_.begin(), staged_.end(),
                               [&](const Staged& s) { return s.destination == destination; });
  if (it == staged_.end()) return;
  std::error_code ec;
  fs::remove_all(it->folder, ec);
  staged_.erase(it);
}

void OutputSet::commit() {
  std::sort(staged_.begin(), staged_.end(), [](const Staged& a, const Staged& b) {
    return key_of(a.destination) < key_of(b.destination);
  });
  std::vector<std::unique_ptr<DestinationLock>> locks;
  for (const Staged& s : staged_) {
    const auto waiting = [&] {
      if (waiting_.waiting) waiting_.waiting(s.destination);
    };
    locks.push_back(std::make_unique<DestinationLock>(s.destination, waiting, waiting_.stop));
  }
  while (!staged_.empty()) {
    const Staged& s = staged_.front();
    try {
      const std::vector<fs::path> made = files_made(s.folder);
      remove_earlier_output(s.destination, made);
      const fs::path folder = folder_of(s.destination);
      for (const fs::path& file : made) fs::rename(file, folder / file.filename());
      fs::remove(s.folder / kStagingMarker);
      fs::remove(s.folder);
    } catch (const fs::filesystem_error& e) {
      throw Error("cannot write '" + s.destination.string() + "': " + e.code().message());
    }
    staged_.erase(staged_.begin());
  }
}

}  // namespace tsk::io
