// Drawn strokes drawn while the stages go on, in three steps on three threads: the pieces grouped;
// the settled groups joined, smoothed and weighed; the strokes handed on. The linking queues its
// steps in the order of the scan (a class's next piece, or where its open chains begin once a
// profile is linked) and gives them to the drawing after each batch.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "core/base/parallel.h"
#include "core/drawn/drawn_strokes.h"
#include "core/method/strokes.h"

namespace tsk {

class DrawingPipeline {
 public:
  // Takes each drawn stroke, in order, on the writing step's thread, with its group (named by
  // its first piece: a class's pieces are numbered from 0 as add_piece queues them, those the
  // drawing drops, shorter than kLeastDrawnCells, not counted).
  using Deliver = std::function<void(StrokeClass cls, std::size_t group, Stroke&& stroke)>;
  // `alongside`: each step on a thread of its own; otherwise each runs as it is given.
  DrawingPipeline(const DrawingSetup& setup, bool alongside, Deliver deliver);
  // A run that ends early (cancelled, failed) leaves what is still to draw undrawn.
  ~DrawingPipeline();
  DrawingPipeline(const DrawingPipeline&) = delete;
  DrawingPipeline& operator=(const DrawingPipeline&) = delete;

  // The longest step between neighbouring points of a piece (StrokeDrawer::longest_step).
  double longest_step() const { return drawers_[0]->longest_step(); }
  // Queues a piece of a complete chain's stroke.
  void add_piece(StrokeClass cls, Stroke&& piece);
  // Queues the settling of the groups that no piece from profile `frontier` on can join (an
  // infinite frontier: all of them).
  void settle(StrokeClass cls, double frontier);
  // Gives the drawing the steps queued. A failed step (a sink that could not write) is rethrown
  // as soon as it is seen; this waits when the drawing falls behind by more than a few batches,
  // whose pieces it would otherwise hold.
  void flush();
  // Steps to a batch. The 8000^2 benchmark's default run, flushed only after each batch of 256
  // profiles, peaked at 720-850 MB; at 8192 steps, 420-460 MB, as fast.
  static constexpr std::size_t kStepsPerBatch = 8192;
  // Flushes once a batch's worth of steps is queued, so that the pieces in flight (a few batches
  // at each step of the drawing) stay bounded however many a batch of profiles makes.
  void flush_when_full() {
    if (steps_.size() >= kStepsPerBatch) flush();
  }
  // Waits for every step given, in order; rethrows the first failure.
  void finish();

 private:
  struct Step {
    StrokeClass cls;
    Stroke piece;     // a step that adds a piece
    double frontier;  // a step that settles groups
    bool settle;
  };
  // The groups a batch of steps took, each class's in one StrokeGroups, and the runs of them in
  // the order they were taken (one StrokeGroups per settling step asked for fresh memory each
  // time: the run's most frequent page fault).
  struct Settled {
    struct Run {
      StrokeClass cls;
      std::size_t from_group, to_group;
    };
    StrokeGroups groups[2];  // factual, formulated
    std::vector<Run> runs;
    StrokeGroups& of(StrokeClass cls) { return groups[class_index(cls)]; }
    void clear() {
      for (StrokeGroups& g : groups) g.clear();
      runs.clear();
    }
  };
  StrokeDrawer& drawer(StrokeClass cls) { return *drawers_[class_index(cls)]; }
  // The grouping: adds the pieces and takes the settled groups, then gives them to the finishing.
  void group(std::vector<Step>& steps);
  // The finishing: draws the groups taken, in order, and gives the strokes to the writing.
  void draw(Settled& settled);

  std::unique_ptr<StrokeDrawer> drawers_[2];      // factual, formulated
  std::vector<Step> steps_;                       // not given to the drawing yet
  BatchStorage<std::vector<Step>> step_storage_;  // of batches of steps the grouping is done with
  BatchStorage<Settled> settled_storage_;         // of the groups drawn
  std::atomic<bool> abandoned_{false};
  // Declared last, in reverse order: each is stopped before the one it gives its work to.
  struct Drawn {
    StrokeClass cls;
    std::size_t group;
    Stroke stroke;
  };
  HandOff<Drawn> writing_;
  TasksBehind finishing_;
  TasksBehind grouping_;
};

}  // namespace tsk
