// Some OGR drivers (GeoJSON, KML, GML) ignore whether their writes succeed: on a full disk they
// close a truncated file as if it were whole. Files that GDAL writes under checked_path() go
// through a file system handler that records every write, flush or close that fails.
#pragma once

#include <filesystem>
#include <string>

namespace tsk::io {

// The name under which GDAL reaches `real` through the check.
std::string checked_path(const std::filesystem::path& real);

// Why the first write that failed in `folder` since the last call failed, e.g. "No space left on
// device" ("" if none did); the failures recorded there are forgotten.
std::string take_write_failure(const std::filesystem::path& folder);

}  // namespace tsk::io
