// The outputs of one run, put in place together. While a set is open on a thread, every output
// written whole on that thread (write_atomically, a QGIS line output) is staged in a private folder
// beside its destination and waits there for commit(), which moves them all in place at once. So a
// run that fails, is interrupted or is killed outright (kill -9, a power cut) leaves the earlier
// outputs, every one of them: never the new statistics beside the old strokes.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

namespace tsk::io {

class OutputSet {
 public:
  // What the commit does while another run holds a destination's lock (destination_lock.h):
  // `waiting` is told which once, and `stop` is called every 100 ms and throws to give up.
  struct Waiting {
    std::function<void(const std::filesystem::path& destination)> waiting;
    std::function<void()> stop;
  };

  // Opens the set on this thread, in place of the one open before (restored when this goes).
  explicit OutputSet(Waiting waiting = {});
  // Removes whatever was staged and not committed.
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // The set open on this thread, or null.
  static OutputSet* current();

  // Makes a staging folder for `destination` (checked with check_output_path) and returns the path
  // to write it at: its file name in that folder. Staging folders that runs killed outright left
  // in the destination's folder are removed first. Throws Error when two outputs of the set have
  // one name.
  std::filesystem::path stage(const std::filesystem::path& destination);

  // Forgets the staged `destination`, removing what was written for it (a write that failed).
  void discard(const std::filesystem::path& destination) noexcept;

  // Moves every staged output in place, each replacing the earlier output's files, under the locks
  // of all their destinations (taken in one order, so that two sets never wait for each other).
  // Throws Error naming the output that could not be put in place.
  void commit();

 private:
  struct Staged {
    std::filesystem::path destination;
    std::filesystem::path folder;  // the staging folder
  };
  std::vector<Staged> staged_;
  Waiting waiting_;
  OutputSet* outer_;  // open on this thread before this one
};

}  // namespace tsk::io
