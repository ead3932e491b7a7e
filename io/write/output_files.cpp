#include "io/write/output_files.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <streambuf>
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

namespace {

// A stream's buffer that goes to an open file a buffer at a time, and remembers the first write
// that failed (the stream then fails too). Its put position counts the bytes put so far.
class FileText : public std::streambuf {
 public:
  explicit FileText(std::FILE* file) : file_(file) { setp(buffer_, buffer_ + sizeof buffer_); }
  int failure() const { return failure_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
  }
  int sync() override { return drain() ? 0 : -1; }
  pos_type seekoff(off_type offset, std::ios_base::seekdir way, std::ios_base::openmode) override {
    if (offset != 0 || way != std::ios_base::cur) return pos_type(off_type(-1));
    return pos_type(static_cast<off_type>(written_ + static_cast<std::size_t>(pptr() - pbase())));
  }

 private:
  bool drain() {
    const auto held = static_cast<std::size_t>(pptr() - pbase());
    if (failure_ != 0) return false;
    if (held > 0 && std::fwrite(pbase(), 1, held, file_) != held) {
      failure_ = errno != 0 ? errno : EIO;
      return false;
    }
    written_ += held;
    setp(buffer_, buffer_ + sizeof buffer_);
    return true;
  }
  std::FILE* file_;
  char buffer_[1 << 16];
  std::size_t written_ = 0;
  int failure_ = 0;
};

}  // namespace

void write_text_file(const fs::path& destination, const std::string& text) {
  write_text_file(destination, [&](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

void write_text_file(const fs::path& destination, const std::function<void(std::ostream&)>& write) {
  write_atomically(destination, [&](const fs::path& staged) {
    std::FILE* file = std::fopen(staged.c_str(), "wb");
    if (!file) throw Error("cannot write '" + destination.string() + "': " + std::strerror(errno));
    FileText text(file);
    std::ostream out(&text);
    try {
      write(out);
    } catch (...) {
      std::fclose(file);
      throw;
    }
    out.flush();
    int reason = text.failure() != 0 ? text.failure() : out ? 0 : EIO;
    if (std::fclose(file) != 0 && reason == 0) reason = errno != 0 ? errno : EIO;
    if (reason != 0)
      throw Error("cannot write '" + destination.string() + "': " + std::strerror(reason));
  });
}

}  // namespace tsk::io
