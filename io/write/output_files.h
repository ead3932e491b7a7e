// Writing outputs whole or not at all: everything goes to a private temporary folder beside the
// destination and is moved into place only when complete.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace tsk::io {

// Throws Error, before any work, if write_atomically could not write `destination`: a path that
// names no file, or a folder that does not exist or cannot be written.
void check_output_path(const std::filesystem::path& destination);

// Calls write(temporary_path) where temporary_path has the destination's file name inside a
// fresh temporary folder next to it; on success moves every file the writer made (a shapefile
// makes several) beside the destination. On any exception nothing is left behind. The staging
// folders that runs killed outright left in the destination's folder are removed first.
void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write);

// Writes `text` to `destination`, whole or not at all; throws Error with the system's reason.
void write_text_file(const std::filesystem::path& destination, const std::string& text);

// The folder a path names a file in ("." for a bare file name).
std::filesystem::path folder_of(const std::filesystem::path& path);

// A path's extension in lower case, with its dot (".tif"); "" for none.
std::string lowercase_extension(const std::filesystem::path& path);

// A hidden file or folder beside `destination`, named after it and ending in `ending`
// (".NAME.lock"); the name is shortened so that one near the 255-byte limit still fits.
std::filesystem::path hidden_beside(const std::filesystem::path& destination,
                                    const std::string& ending);

}  // namespace tsk::io
