// Which of a raster's blocks a reader going down the raster lets GDAL drop, and when.
//
// Readers go down a DEM in passes: a cardinal view from the west in one pass of full-width strips;
// other views in bands of columns (north and south) or of slanting rows (every other azimuth),
// each band a pass from its top. A block row is let go once a pass has gone past it, so that GDAL
// holds about a run of block rows whatever its cache's size (in QGIS, a share of the machine's
// memory). Consecutive bands share the blocks along their common edge. Dropped with the rest, each
// was inflated again by the next band (+40 % of a run's inflating from 0 and 180 degrees on the
// 8000^2 benchmark, +72 % from 45 degrees in strips of 370 profiles). So in each block row a pass
// leaves, the blocks at either side of the columns it read stay for the next pass, as wide as a
// block and as far as the band's edge slants across the block row; but not a side the passes are
// moving away from, nor any of a block row read across the whole width, nor every block of a row
// (a file in strips has a block to a row, which every band reads whole).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace tsk::io {

class BlockRetention {
 public:
  // Lets GDAL drop the block in block column `x` of block row `y`.
  using Drop = std::function<void(std::size_t x, std::size_t y)>;
  BlockRetention(std::size_t rows, std::size_t cols, std::size_t block_rows, std::size_t block_cols,
                 Drop drop);

  // Rows [top, end) of columns [col0, col0 + cols) have been read (an empty read changes nothing).
  // A read that starts above the block rows this pass still holds starts a new pass.
  void read(std::size_t top, std::size_t end, std::size_t col0, std::size_t cols);
  // Lets go of the block rows above block row `keep`: no read of this pass comes back to them.
  void let_go_above(std::size_t keep);

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  // Block columns [first, last]; none when first > last.
  struct Blocks {
    std::size_t first = 1, last = 0;
    bool has(std::size_t x) const { return first <= x && x <= last; }
    bool empty() const { return first > last; }
  };
  static bool either_has(const Blocks kept[2], std::size_t x) {
    return kept[0].has(x) || kept[1].has(x);
  }
  // What one block row holds for the passes: the columns this pass and the last one read there,
  // the blocks kept for the next pass, and where this pass's first and latest reads there ended
  // (the row after each, and its first and last column), to see how far the band's edge slants.
  struct BlockRow {
    std::size_t first_col = kNone, last_col = 0;
    std::size_t before_first_col = kNone, before_last_col = 0;
    Blocks kept[2];  // at the side of the first columns, and of the last ones
    std::size_t start_end = 0, latest_end = 0;
    std::size_t start_cols[2] = {0, 0}, latest_cols[2] = {0, 0};
  };
  void let_go(std::size_t y);
  // The blocks of block row y to keep for the next pass.
  void choose_kept(std::size_t y, Blocks kept[2]) const;
  // Whether `kept` is every block of a block row.
  bool covers_row(const Blocks kept[2]) const;
  // How far the band's edge at a side (0: first columns, 1: last) slants across a block row, by
  // how far that side's column moved from the pass's first read of the row to its latest.
  std::size_t slant(const BlockRow& row, int side) const;

  std::size_t block_rows_, block_cols_, cols_;
  std::size_t block_row_count_, blocks_per_row_;
  Drop drop_;
  // Of every block row, when a block row has more than one block (a file in strips has one per
  // row, which every band reads whole: none is kept, so none is followed).
  std::vector<BlockRow> rows_;
  std::size_t held_from_ = kNone, held_to_ = 0;  // block rows read in this pass, not let go
};

}  // namespace tsk::io
