// Writing outputs whole or not at all: everything goes to a private temporary folder beside the
// destination and is moved into place only when complete, together with the run's other outputs
// (output_set.h).
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace tsk::io {

// Throws Error, before any work, if write_atomically could not write `destination`: a path that
// names no file, a folder that does not exist or cannot be written, something other than a file
// there, or a member of another dataset (a shapefile's .dbf). Returns the destination's folder.
std::filesystem::path check_output_path(const std::filesystem::path& destination);

// Calls write(temporary_path) where temporary_path has the destination's file name inside a
// fresh staging folder next to it (OutputSet::stage). The output waits there for the commit of
// the output set open on this thread, or, with none open, is committed at once: every file the
// writer made (a shapefile makes several) is moved beside the destination. On any exception
// nothing is left behind.
void write_atomically(const std::filesystem::path& destination,
                      const std::function<void(const std::filesystem::path&)>& write);

// Writes `text` to `destination`, whole or not at all; throws Error with the system's reason.
void write_text_file(const std::filesystem::path& destination, const std::string& text);
// The same for text made as it is written: `write` puts it in a stream that goes to the file a
// buffer at a time, whose tellp() counts the bytes put so far (a page of vector art made whole
// first took five copies of 365 MB for the 8000^2 defaults' PDF).
void write_text_file(const std::filesystem::path& destination,
                     const std::function<void(std::ostream&)>& write);

// The folder a path names a file in ("." for a bare file name).
std::filesystem::path folder_of(const std::filesystem::path& path);

// A path's extension in lower case, with its dot (".tif"); "" for none.
std::string lowercase_extension(const std::filesystem::path& path);

// A hidden file or folder beside `destination`, named after it and ending in `ending`
// (".NAME.lock"); the name is shortened so that one near the 255-byte limit still fits.
std::filesystem::path hidden_beside(const std::filesystem::path& destination,
                                    const std::string& ending);

}  // namespace tsk::io
