// The strokes of closed chains held until every chain started before theirs has closed too, then
// handed on oldest first: the order of SPEC 1.7's scan, whatever order the chains close in. Keyed
// by any numbers in the scan's order (the bands' stitcher keys chains by their first cells); a
// run's own chains, numbered as they start, are held by ChainOrder (chain_order.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/method/stroke_slots.h"
#include "core/method/strokes.h"

namespace tsk {

class ScanOrder {
 public:
  // Holds a stroke of chain `chain`, or its piece `piece` (drawn strokes: pieces in order).
  void hold(std::size_t chain, std::size_t piece, Stroke&& stroke) {
    const std::size_t slot = slots_.put(std::move(stroke));
    heap_.push_back({chain, piece, slot});
    std::push_heap(heap_.begin(), heap_.end(), later);
  }

  // Hands use(stroke, chain, piece) every stroke held of the chains started before chain
  // `chain`, oldest first.
  template <typename Use>
  void release_before(std::size_t chain, Use&& use) {
    while (!heap_.empty() && heap_.front().chain < chain) {
      std::pop_heap(heap_.begin(), heap_.end(), later);
      const Held held = heap_.back();
      heap_.pop_back();
      // A stroke waits in its slot long enough to leave the cache: the next one, and both that
      // may come after it, are fetched while this one is handed on.
      for (std::size_t k = 0; k < 3 && k < heap_.size(); ++k) slots_.prefetch(heap_[k].slot);
      use(slots_.take(held.slot), held.chain, held.piece);
    }
  }

 private:
  // The heap orders small keys; the strokes stay in their slots.
  struct Held {
    std::size_t chain;
    std::size_t piece;
    std::size_t slot;  // in slots_
  };
  // The heap's order: the oldest chain, and its first piece, on top.
  static bool later(const Held& a, const Held& b) {
    return a.chain != b.chain ? a.chain > b.chain : a.piece > b.piece;
  }
  std::vector<Held> heap_;
  StrokeSlots slots_;
};

}  // namespace tsk
