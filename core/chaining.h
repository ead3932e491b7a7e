// Stage 6 (SPEC 1.7): linking occluding cells and t-set cells across profiles into chains.
#pragma once

#include <cstdint>
#include <vector>

#include "flags.h"
#include "parallel.h"

namespace tsk {

struct ChainCell {
  std::int32_t p;  // profile
  std::int32_t i;  // cell along the profile
};

// Cells of one chain, one per profile, in consecutive profiles left to right.
using Chain = std::vector<ChainCell>;

// Factual Silhouettes: an occluding cell links to the unused occluding cell on the next profile
// whose [cell, end of hidden zone] interval overlaps its own, nearest first, ties to the front.
std::vector<Chain> chain_factual(const CellFlags& flags, unsigned threads = 0,
                                 const ProgressFn& progress = {});

// Formulated Silhouettes: a t-set cell links to the unused t-set cell on the next profile within
// `window` cells, nearest first, ties to the front. Chains of one cell are never returned.
std::vector<Chain> chain_formulated(const CellFlags& flags, int window, unsigned threads = 0,
                                    const ProgressFn& progress = {});

}  // namespace tsk
