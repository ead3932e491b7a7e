// Strokes waiting in slots whose storage is reused, for the classes that hand strokes on in the
// scan's order (ScanOrder, ChainOrder): a stroke stays in its slot while it waits, and only small
// keys move (sifting the strokes themselves cost 5 % of a default run).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/base/prefetch.h"
#include "core/method/strokes.h"

namespace tsk {

class StrokeSlots {
 public:
  // Puts `stroke` in a free slot, or in a new one; returns the slot.
  std::size_t put(Stroke&& stroke) {
    if (free_.empty()) {
      strokes_.push_back(std::move(stroke));
      return strokes_.size() - 1;
    }
    const std::size_t slot = free_.back();
    free_.pop_back();
    // A slot stays free long enough to leave the cache: the next one to fill is fetched now.
    if (!free_.empty()) prefetch_record_to_write(strokes_[free_.back()]);
    strokes_[slot] = std::move(stroke);
    return slot;
  }
  // Asks the processor for the stroke in `slot`: a stroke waits long enough to leave the cache.
  void prefetch(std::size_t slot) const { prefetch_record(strokes_[slot]); }
  // The stroke waiting in `slot`.
  const Stroke& at(std::size_t slot) const { return strokes_[slot]; }
  // Takes the stroke out of `slot`, which is free again; its memory goes with it.
  Stroke take(std::size_t slot) {
    free_.push_back(slot);
    return std::move(strokes_[slot]);
  }

 private:
  std::vector<Stroke> strokes_;
  std::vector<std::size_t> free_;  // slots taken from
};

}  // namespace tsk
