// The strokes of closed chains held until every chain started before theirs has closed too, then
// handed on oldest first: the order of SPEC 1.7's scan, whatever order the chains close in.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/method/strokes.h"

namespace tsk {

class ScanOrder {
 public:
  // Holds a stroke of chain `chain`, or its piece `piece` (drawn strokes: pieces in order).
  void hold(std::size_t chain, std::size_t piece, Stroke&& stroke) {
    heap_.push_back({chain, piece, std::move(stroke)});
    std::push_heap(heap_.begin(), heap_.end(), later);
  }

  // Hands use(stroke) every stroke held of the chains started before chain `chain`, oldest
  // first.
  template <typename Use>
  void release_before(std::size_t chain, Use&& use) {
    while (!heap_.empty() && heap_.front().chain < chain) {
      std::pop_heap(heap_.begin(), heap_.end(), later);
      Stroke stroke = std::move(heap_.back().stroke);
      heap_.pop_back();
      use(std::move(stroke));
    }
  }

 private:
  struct Held {
    std::size_t chain;
    std::size_t piece;
    Stroke stroke;
  };
  // The heap's order: the oldest chain, and its first piece, on top.
  static bool later(const Held& a, const Held& b) {
    return a.chain != b.chain ? a.chain > b.chain : a.piece > b.piece;
  }
  std::vector<Held> heap_;
};

}  // namespace tsk
