#include "io/read/block_retention.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tsk::io {

BlockRetention::BlockRetention(std::size_t rows, std::size_t cols, std::size_t block_rows,
                               std::size_t block_cols, Drop drop)
    : block_rows_(std::max<std::size_t>(1, block_rows)),
      block_cols_(std::max<std::size_t>(1, block_cols)),
      cols_(cols),
      block_row_count_((rows + block_rows_ - 1) / block_rows_),
      blocks_per_row_((cols + block_cols_ - 1) / block_cols_),
      drop_(std::move(drop)),
      rows_(blocks_per_row_ > 1 ? block_row_count_ : 0) {}

void BlockRetention::read(std::size_t top, std::size_t end, std::size_t col0, std::size_t cols) {
  if (block_row_count_ == 0 || end <= top || cols == 0) return;
  const std::size_t y0 = std::min(top / block_rows_, block_row_count_ - 1);
  const std::size_t y1 = std::min((end - 1) / block_rows_, block_row_count_ - 1);
  if (held_from_ != kNone && y0 < held_from_) {
    // Back above the rows this pass holds: the next band. Its rows below are let go now.
    let_go_above(held_to_);
  }
  held_from_ = std::min(held_from_, y0);
  held_to_ = std::max(held_to_, y1 + 1);
  if (rows_.empty()) return;  // no block is kept, so no read is followed
  const std::size_t last = col0 + cols - 1;
  for (std::size_t y = y0; y <= y1; ++y) {
    BlockRow& row = rows_[y];
    if (row.first_col == kNone) {
      row.start_end = end;
      row.start_cols[0] = col0, row.start_cols[1] = last;
    }
    row.latest_end = end;
    row.latest_cols[0] = col0, row.latest_cols[1] = last;
    row.first_col = std::min(row.first_col, col0);
    row.last_col = std::max(row.last_col, last);
  }
}

void BlockRetention::let_go_above(std::size_t keep) {
  if (held_from_ == kNone) return;
  const std::size_t to = std::min(keep, held_to_);
  for (std::size_t y = held_from_; y < to; ++y) let_go(y);
  held_from_ = std::max(held_from_, to);
  if (held_from_ >= held_to_) held_from_ = kNone, held_to_ = 0;
}

std::size_t BlockRetention::slant(const BlockRow& row, int side) const {
  const auto rows_between = static_cast<double>(row.latest_end - row.start_end);
  if (!(rows_between > 0.0)) return 0;
  const std::size_t from = row.start_cols[side], to = row.latest_cols[side];
  const auto moved = static_cast<double>(from > to ? from - to : to - from);
  return static_cast<std::size_t>(
      std::ceil(moved / rows_between * static_cast<double>(block_rows_)));
}

void BlockRetention::choose_kept(std::size_t y, Blocks kept[2]) const {
  const BlockRow& row = rows_[y];
  // A row read across the whole width (strips from the west) is not read again.
  if (row.first_col == 0 && row.last_col + 1 >= cols_) return;
  const bool had_pass = row.before_first_col != kNone;
  const bool toward_last = had_pass && row.first_col > row.before_first_col;
  const bool toward_first = had_pass && row.last_col < row.before_last_col;
  if (!toward_last) {
    const std::size_t width = block_cols_ + slant(row, 0);
    const std::size_t to = std::min(row.last_col, row.first_col + width - 1);
    kept[0] = {row.first_col / block_cols_, to / block_cols_};
  }
  if (!toward_first) {
    const std::size_t width = std::min(block_cols_ + slant(row, 1), row.last_col + 1);
    const std::size_t from = std::max(row.first_col, row.last_col + 1 - width);
    kept[1] = {from / block_cols_, row.last_col / block_cols_};
  }
  // Keeping every block of the row would hold the whole file as the bands go by.
  if (covers_row(kept)) kept[0] = kept[1] = Blocks{};
}

bool BlockRetention::covers_row(const Blocks kept[2]) const {
  const bool gap_between = !kept[0].empty() && !kept[1].empty() && kept[1].first > kept[0].last + 1;
  return either_has(kept, 0) && either_has(kept, blocks_per_row_ - 1) && !gap_between;
}

void BlockRetention::let_go(std::size_t y) {
  if (rows_.empty()) {
    drop_(0, y);
    return;
  }
  BlockRow& row = rows_[y];
  if (row.first_col == kNone) return;  // not read in this pass: what it keeps stays kept
  Blocks kept[2];
  choose_kept(y, kept);
  const Blocks read{row.first_col / block_cols_, row.last_col / block_cols_};
  for (std::size_t x = read.first; x <= read.last; ++x)
    if (!either_has(kept, x)) drop_(x, y);
  for (const Blocks& before : row.kept) {
    for (std::size_t x = before.first; x <= before.last; ++x)
      if (!read.has(x) && !either_has(kept, x)) drop_(x, y);
  }
  row.kept[0] = kept[0];
  row.kept[1] = kept[1];
  row.before_first_col = row.first_col;
  row.before_last_col = row.last_col;
  row.first_col = kNone;
  row.last_col = 0;
}

}  // namespace tsk::io
