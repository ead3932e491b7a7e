// Stage 6 (SPEC 1.7): linking occluding cells and t-set cells across profiles into chains.
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/base/scratch_vector.h"

namespace tsk {

struct ChainCell {
  std::int32_t p;  // profile
  std::int32_t i;  // cell along the profile
};

// Cells of one chain, one per profile, in consecutive profiles left to right.
using Chain = std::vector<ChainCell>;

// The cells of one profile that may join chains, front to back. For factual chaining `reach` is
// the last cell of the hidden zone behind each cell; for formulated chaining the cell itself.
// (Scratch vectors: the t-set's are sized to the profile, then written, then cut to their count.)
struct ProfileCandidates {
  ScratchVector<std::int32_t> cell;
  ScratchVector<std::int32_t> reach;
};

// The candidates of profile p: occluding cells with their hidden zones (factual) or t-set cells,
// among cells [first, length), into `out` (whose storage is reused).
void profile_candidates(const std::uint8_t* flags, std::size_t length, bool factual,
                        ProfileCandidates& out, std::size_t first = 0);

// Two chains, as the indices of their cells in a profile: `before` took a cell that `after`, later
// in the order of the chains, would otherwise have taken.
struct OrderPair {
  std::uint32_t before, after;
  bool operator<(const OrderPair& o) const {
    return before != o.before ? before < o.before : after < o.after;
  }
  bool operator==(const OrderPair& o) const { return before == o.before && after == o.after; }
};

// A chain as the linker reports it: its id (ids count up in the order chains are started) and
// its slot, a small index that a closed chain hands on to a later one, so a caller can keep the
// cells of open chains in a vector indexed by slot and reuse its storage.
struct ChainRef {
  std::size_t id;
  std::uint32_t slot;
};

// Links profiles given one at a time, left to right, as SPEC 1.7 scans them: every chain is grown
// as far right as it goes before the next unused cell (front to back) starts one. In each new
// profile the open chains pick their cell in the order they were started (older first), nearest
// first, ties to the front; the cells left over start new chains. Holds two profiles at a time.
class ChainLinker {
 public:
  ChainLinker(bool factual, int window);

  // Links the next profile. Returns, for each of its candidates, the chain it joined.
  const std::vector<ChainRef>& add_profile(const ProfileCandidates& candidates);
  // The chains that the last add_profile() could not extend: they are complete. Their slots are
  // handed on only from the next call on.
  const std::vector<ChainRef>& closed() const { return closed_; }
  // Closes every chain still open (after the last profile) and returns them.
  const std::vector<ChainRef>& close_all();
  // One more than the largest slot handed out so far.
  std::size_t slot_count() const { return slot_count_; }
  // The id of the oldest chain still open (the next id when none is): every chain with a smaller
  // id is complete.
  std::size_t oldest_open() const { return open_.empty() ? started_ : open_.front().chain.id; }
  // The oldest chain still open, when one is.
  const ChainRef* oldest_open_chain() const {
    return open_.empty() ? nullptr : &open_.front().chain;
  }

  struct Open {
    ChainRef chain;
    std::size_t k;  // index of the chain's last cell in the last profile
  };
  // The chains open after the last profile, oldest first: one per candidate of that profile.
  const std::vector<Open>& open() const { return open_; }
  // Starts as if `last` had just been linked with its candidates' chains open in `order` (the
  // candidates' indices, oldest chain first), as a run from the grid's first profile would have
  // left them: what a band of profiles links from (bands.h). Throws Error unless `order` holds
  // each candidate once.
  void start_from(const ProfileCandidates& last, const std::vector<std::uint32_t>& order);
  // From now on, records the pairs of chains open now (a band's chains crossing in from the band
  // before) whose order decided a join: one took a cell the other would rather have had. Linked
  // from another order of these chains that keeps every such pair, the same profiles join every
  // cell alike (each chain's choice depends only on the cells taken before it).
  void record_deciding_pairs();
  // The pairs recorded, as the indices of their chains' cells in the profile linked last when
  // recording began; each once.
  std::vector<OrderPair> deciding_pairs() const;

 private:
  std::uint32_t take_slot();
  // Records the chains crossing in that took, before `o`, a cell `o` would rather have had than
  // its choice `found` (any it could reach, when it found none).
  void note_deciding_claims(const ProfileCandidates& next, const Open& o, std::int32_t hi,
                            std::ptrdiff_t found);
  std::uint32_t crossing_cell(std::size_t id) const;

  bool factual_;
  int window_;
  ProfileCandidates last_;
  // Open chains in the order they were started: the survivors keep their order, new ones follow.
  std::vector<Open> open_, still_open_;
  std::vector<ChainRef> joined_, closed_;
  std::vector<std::uint8_t> used_;
  std::vector<std::size_t> search_from_;  // per candidate of the last profile
  std::vector<std::uint32_t> free_slots_;
  std::size_t started_ = 0;
  std::uint32_t slot_count_ = 0;
  // Recording deciding pairs: chains with ids below crossing_end_ cross in (none until
  // record_deciding_pairs); their ids (rising) and cells where recording began.
  std::size_t crossing_end_ = 0;
  std::vector<std::size_t> crossing_ids_;
  std::vector<std::uint32_t> crossing_cells_;
  std::vector<OrderPair> deciding_;
};

}  // namespace tsk
