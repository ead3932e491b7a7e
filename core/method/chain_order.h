// The strokes of a run's closed chains held until every chain started before theirs has closed
// too, then handed on oldest first: the order of SPEC 1.7's scan, whatever order the chains close
// in. For chains numbered from 0 as they start, by a table indexed by chain: handing on walks it
// in order, where a heap (ScanOrder, for keys that are not dense) sifted through many strokes held
// at once (34 000 on the 8000^2 benchmark's defaults) and missed the cache at each level.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/base/errors.h"
#include "core/method/stroke_slots.h"
#include "core/method/strokes.h"

namespace tsk {

class ChainOrder {
 public:
  // Holds piece `piece` of chain `chain`'s stroke (0 for an exact stroke). A chain's pieces come
  // one after another, from 0; a chain is held after every chain handed on so far.
  void hold(std::size_t chain, std::size_t piece, Stroke&& stroke) {
    if (chain < table_start_ + released_)
      throw Error("a stroke held for a chain already handed on");
    if (piece > 0 && (chain != last_chain_ || last_slot_ == kNone))
      throw Error("a chain's pieces held apart from each other");
    const std::size_t at = chain - table_start_;
    if (piece == 0) {
      if (firsts_.size() <= at) firsts_.resize(at + 1, kNone);
      if (firsts_[at] != kNone) throw Error("a chain's stroke held twice");
    }
    const std::size_t put = slots_.put(std::move(stroke));
    if (put >= kNone) throw Error("too many strokes held at once");
    const auto slot = static_cast<std::uint32_t>(put);
    if (next_.size() <= slot) next_.resize(slot + std::size_t{1});
    next_[slot] = kNone;
    (piece > 0 ? next_[last_slot_] : firsts_[at]) = slot;
    last_chain_ = chain;
    last_slot_ = slot;
  }

  // Hands use(stroke) every stroke held of the chains started before chain `chain`, oldest
  // first, each chain's pieces in order.
  template <typename Use>
  void release_before(std::size_t chain, Use&& use) {
    const std::size_t end = std::min(chain - std::min(chain, table_start_), firsts_.size());
    due_.clear();
    for (std::size_t at = released_; at < end; ++at) {
      for (std::uint32_t s = firsts_[at]; s != kNone; s = next_[s]) due_.push_back(s);
    }
    released_ = std::max(released_, end);
    // A stroke waits in its slot long enough to leave the cache: those a few places on are
    // fetched while one is handed on.
    constexpr std::size_t kAhead = 3;
    for (std::size_t k = 0; k < std::min(kAhead, due_.size()); ++k) slots_.prefetch(due_[k]);
    for (std::size_t k = 0; k < due_.size(); ++k) {
      if (k + kAhead < due_.size()) slots_.prefetch(due_[k + kAhead]);
      use(slots_.take(due_[k]));
    }
    forget_released();
  }

  // Hands use(stroke) every stroke held, oldest chain first, `chains_per_run` chains at a time;
  // after each run but the last, calls settle(frontier) with the least profile a stroke still
  // held reaches: the least first cell's profile of their chains' first pieces (a chain's cells
  // run from profile to profile, left to right).
  template <typename Use, typename Settle>
  void release_all_in_runs(std::size_t chains_per_run, Use&& use, Settle&& settle) {
    std::vector<std::size_t> chains;
    std::vector<double> frontier;  // by chain held: the least first profile from it on
    for (std::size_t at = released_; at < firsts_.size(); ++at) {
      if (firsts_[at] == kNone) continue;
      const Chain& cells = slots_.at(firsts_[at]).chain;
      chains.push_back(table_start_ + at);
      frontier.push_back(cells.empty() ? -std::numeric_limits<double>::infinity()
                                       : static_cast<double>(cells.front().p));
    }
    for (std::size_t k = frontier.size(); k-- > 1;)
      frontier[k - 1] = std::min(frontier[k - 1], frontier[k]);
    const std::size_t step = std::max<std::size_t>(1, chains_per_run);
    for (std::size_t k = step; k < chains.size(); k += step) {
      release_before(chains[k], use);
      settle(frontier[k]);
    }
    release_before(std::numeric_limits<std::size_t>::max(), use);
  }

 private:
  static constexpr std::uint32_t kNone = static_cast<std::uint32_t>(-1);
  static constexpr std::size_t kForgetAtLeast = 4096;  // chains' entries, to forget at once

  // Drops the entries of chains handed on once they are most of the table, to move few.
  void forget_released() {
    if (released_ < kForgetAtLeast || 2 * released_ < firsts_.size()) return;
    firsts_.erase(firsts_.begin(), firsts_.begin() + static_cast<std::ptrdiff_t>(released_));
    table_start_ += released_;
    released_ = 0;
  }

  std::size_t table_start_ = 0;        // the chain of firsts_[0]
  std::size_t released_ = 0;           // entries of firsts_ handed on
  std::vector<std::uint32_t> firsts_;  // by chain from table_start_: its first piece's slot
  StrokeSlots slots_;
  std::vector<std::uint32_t> next_;  // by slot: the slot of the chain's next piece
  std::vector<std::uint32_t> due_;   // slots to hand on, its storage reused
  std::size_t last_chain_ = 0;
  std::uint32_t last_slot_ = kNone;
};

}  // namespace tsk
