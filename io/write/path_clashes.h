// Outputs that would write over what a run reads, or over each other: checked alike by every
// front end before any work, each wording the clash its own way.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tsk::io {

struct NamedFile {
  std::string name;  // the front end's name for it: "--preview", "Factual silhouettes"
  std::string path;  // empty: not given
  // An output written whole over its file. False for a layer added to a file, which may share
  // the file with another added layer.
  bool whole = true;
};

struct PathClash {
  NamedFile output;  // the output that would write over...
  NamedFile other;   // ...this input, or this output listed before it
  bool with_input;   // whether `other` is an input
  std::string file;  // the file they share, as the input reads it
};

// True when a and b name one file: the same existing file, or the same path to be made.
bool same_file(const std::string& a, const std::string& b);

// The first clash: an output naming a file that an input reads (the input's file and every file
// read for it, all the way down: files_read_for), or two outputs naming one file unless both are
// added layers. Inputs are checked first, outputs in their order. Throws Error when an input
// reads a source that is not a file (check_sources_are_files): a pipe GDAL would hang on.
std::optional<PathClash> find_clash(const std::vector<NamedFile>& outputs,
                                    const std::vector<NamedFile>& inputs);

}  // namespace tsk::io
