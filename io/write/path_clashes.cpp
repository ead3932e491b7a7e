#include "io/write/path_clashes.h"

#include <filesystem>
#include <system_error>

#include "io/read/gdal_util.h"

namespace tsk::io {

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  const auto full_a = std::filesystem::weakly_canonical(a, ec);
  if (ec) return false;
  const auto full_b = std::filesystem::weakly_canonical(b, ec);
  return !ec && full_a == full_b;
}

std::optional<PathClash> find_clash(const std::vector<NamedFile>& outputs,
                                    const std::vector<NamedFile>& inputs) {
  // Every file read for each input, all the way down; none may be a pipe or a device.
  std::vector<std::vector<std::string>> read(inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (inputs[k].path.empty()) continue;
    read[k] = files_read_for(inputs[k].path);
    check_sources_are_files(inputs[k].path, read[k]);
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedFile& output = outputs[k];
    if (output.path.empty()) continue;
    for (std::size_t j = 0; j < inputs.size(); ++j) {
      for (const std::string& file : read[j]) {
        if (same_file(output.path, file)) return PathClash{output, inputs[j], true, file};
      }
    }
    for (std::size_t j = 0; j < k; ++j) {
      const NamedFile& other = outputs[j];
      if ((output.whole || other.whole) && same_file(output.path, other.path))
        return PathClash{output, other, false, output.path};
    }
  }
  return std::nullopt;
}

}  // namespace tsk::io
