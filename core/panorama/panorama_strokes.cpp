#include "core/panorama/panorama_strokes.h"

#include <algorithm>
#include <cstdlib>

namespace tsk {

PanoramaLinker::PanoramaLinker(bool factual, int window, int min_cells, bool full_circle,
                               std::int32_t leap_samples)
    : factual_(factual),
      full_circle_(full_circle),
      leap_samples_(leap_samples),
      window_(window),
      min_cells_(min_cells),
      linker_(factual, window) {}

void PanoramaLinker::add_ray(std::size_t r, const ProfileCandidates& candidates,
                             const std::vector<StrokeCell>& cells,
                             const std::vector<StrokePoint>& view) {
  const std::vector<ChainRef>& joined = linker_.add_profile(candidates);
  if (open_.size() < linker_.slot_count()) open_.resize(linker_.slot_count());
  for (std::size_t k = 0; k < joined.size(); ++k) {
    Open& open = open_[joined[k].slot];
    // A leap along the ray is no line on the terrain: the stroke so far ends, the chain goes on
    // as a stroke of its own (as drawn strokes of the parallel view are cut).
    if (leap_samples_ > 0 && open.builder.cells() > 0 &&
        std::abs(cells[k].cell.i - open.last_sample) > leap_samples_)
      close(open);
    if (open.builder.cells() == 0) {
      open.id = joined[k].id;
      open.from_first_ray = r == 0 && full_circle_;
    }
    open.builder.add(cells[k]);
    open.last_sample = cells[k].cell.i;
    open.view.push_back(view[k]);
    if (open.from_first_ray) open.cells.push_back(cells[k]);
  }
  for (const ChainRef& ref : linker_.closed()) close(open_[ref.slot]);
  if (r == 0) first_ = candidates, first_joined_ = joined;
  last_ = candidates;
  last_joined_ = joined;
}

void PanoramaLinker::close(Open& open) {
  if (open.from_first_ray) {
    held_.push_back(std::move(open));
  } else {
    keep(open.id, open);
  }
  open = Open{};
}

void PanoramaLinker::keep(std::size_t id, Open& open) {
  if (open.builder.cells() < min_cells_) return;
  PanoramaStroke stroke;
  stroke.map = open.builder.take(factual_ ? StrokeClass::factual : StrokeClass::formulated);
  stroke.view = std::move(open.view);
  const auto [lo, hi] =
      std::minmax_element(stroke.view.begin(), stroke.view.end(),
                          [](const StrokePoint& a, const StrokePoint& b) { return a.x < b.x; });
  stroke.azimuth_min = lo->x;
  stroke.azimuth_max = hi->x;
  kept_.emplace_back(id, std::move(stroke));
}

// A chain open on the last ray continues a held chain of the first ray when SPEC 1.7 links the
// last ray's candidates to the first's: the held chain's cells are added to it, its panorama
// points a turn further on, so that a stroke across the seam stays whole.
void PanoramaLinker::close_seam(const std::vector<ChainRef>& last_joined) {
  ChainLinker seam(factual_, window_);
  seam.add_profile(last_);  // starts chain k for the last ray's candidate k
  const std::vector<ChainRef> across = seam.add_profile(first_);
  for (std::size_t j = 0; j < across.size(); ++j) {
    const std::size_t k = across[j].id;
    if (k >= last_.cell.size()) continue;  // started a chain of its own: nothing to join
    Open& before = open_[last_joined[k].slot];
    if (before.from_first_ray) continue;  // a chain round the whole circle is not wound twice
    const std::size_t id = first_joined_[j].id;
    const auto held =
        std::find_if(held_.begin(), held_.end(), [id](const Open& h) { return h.id == id; });
    if (held == held_.end()) continue;
    // Across the seam as along the rays: a leap joins nothing.
    if (leap_samples_ > 0 &&
        std::abs(held->cells.front().cell.i - before.last_sample) > leap_samples_)
      continue;
    for (std::size_t c = 0; c < held->cells.size(); ++c) {
      before.builder.add(held->cells[c]);
      before.view.push_back({held->view[c].x + 360.0, held->view[c].y});
    }
    held_.erase(held);
  }
}

std::vector<PanoramaStroke> PanoramaLinker::finish() {
  const std::vector<ChainRef> last_joined = last_joined_;
  if (full_circle_ && !first_joined_.empty()) close_seam(last_joined);
  for (const ChainRef& ref : linker_.close_all()) {
    Open& open = open_[ref.slot];
    if (open.builder.cells() > 0) keep(open.id, open);
    open = Open{};
  }
  for (Open& held : held_) keep(held.id, held);
  held_.clear();
  std::sort(kept_.begin(), kept_.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<PanoramaStroke> strokes;
  strokes.reserve(kept_.size());
  for (auto& [id, stroke] : kept_) strokes.push_back(std::move(stroke));
  kept_.clear();
  return strokes;
}

}  // namespace tsk
