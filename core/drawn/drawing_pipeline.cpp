#include "core/drawn/drawing_pipeline.h"

#include <algorithm>
#include <utility>

namespace tsk {
namespace {

// Batches each step of the drawing may have still to do before the step before it waits.
constexpr std::size_t kBatchesBehind = 2;

}  // namespace

DrawingPipeline::DrawingPipeline(const DrawingSetup& setup, bool alongside, Deliver deliver)
    : drawers_{std::make_unique<StrokeDrawer>(setup), std::make_unique<StrokeDrawer>(setup)},
      writing_([deliver = std::move(deliver)](
                   Drawn&& drawn) { deliver(drawn.cls, drawn.group, std::move(drawn.stroke)); },
               alongside),
      finishing_(kBatchesBehind, alongside),
      grouping_(kBatchesBehind, alongside) {}

DrawingPipeline::~DrawingPipeline() {
  abandoned_ = true;
}

void DrawingPipeline::add_piece(StrokeClass cls, Stroke&& piece) {
  steps_.push_back({cls, std::move(piece), 0.0, false});
}

void DrawingPipeline::settle(StrokeClass cls, double frontier) {
  steps_.push_back({cls, Stroke(), frontier, true});
}

void DrawingPipeline::flush() {
  if (steps_.empty()) return;
  auto taken = std::make_shared<std::vector<Step>>(std::move(steps_));
  steps_ = step_storage_.take();
  // A batch of steps runs to kStepsPerBatch and a profile's worth beyond, or stops short at the
  // end of a batch of profiles: room for a full one, not a doubling series of moves.
  steps_.reserve(std::max(taken->size(), kStepsPerBatch + kStepsPerBatch / 8));
  grouping_.run([this, taken] { group(*taken); });
}

void DrawingPipeline::group(std::vector<Step>& steps) {
  auto settled = std::make_shared<Settled>(settled_storage_.take());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (abandoned_) return;
    Step& step = steps[k];
    // The pieces were made on the linking thread: the one after next is fetched while this one
    // is grouped, and what the next one will look up in the groups' index.
    if (k + 2 < steps.size() && !steps[k + 2].settle) prefetch_piece_ends(steps[k + 2].piece);
    if (k + 1 < steps.size() && !steps[k + 1].settle)
      drawer(steps[k + 1].cls).prefetch(steps[k + 1].piece);
    if (step.settle) {
      StrokeGroups& groups = settled->of(step.cls);
      const std::size_t before = groups.ends.size();
      drawer(step.cls).take_settled(step.frontier, groups);
      if (groups.ends.size() > before)
        settled->runs.push_back({step.cls, before, groups.ends.size()});
    } else {
      drawer(step.cls).add(std::move(step.piece));
    }
  }
  step_storage_.give_back(std::move(steps));
  finishing_.run([this, settled] { draw(*settled); });
}

void DrawingPipeline::draw(Settled& settled) {
  for (const Settled::Run& run : settled.runs) {
    if (abandoned_) return;
    const StrokeClass of = run.cls;
    drawer(of).draw(settled.of(of), run.from_group, run.to_group,
                    [&](std::size_t group, Stroke&& stroke) {
                      writing_.add({of, group, std::move(stroke)});
                    });
  }
  settled_storage_.give_back(std::move(settled));
  writing_.flush();
}

void DrawingPipeline::finish() {
  grouping_.finish();
  finishing_.finish();
  writing_.finish();
}

}  // namespace tsk
