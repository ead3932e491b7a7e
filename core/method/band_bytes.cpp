// Band sketches as bytes (bands.h): what a cluster's worker hands its client.
#include "core/base/byte_stream.h"
#include "core/method/bands.h"

namespace tsk {
namespace {

constexpr std::uint32_t kBandMagic = 0x54534b42;   // "TSKB"
constexpr std::uint32_t kOrderMagic = 0x54534b4f;  // "TSKO"

void put_orders(ByteWriter& w, const BandOrders& o) {
  w.put(o.factual);
  w.put(o.formulated);
}

void get_orders(ByteReader& r, BandOrders& o) {
  r.get(o.factual);
  r.get(o.formulated);
}

constexpr std::uint32_t kFilterMagic = 0x54534b46;  // "TSKF"

// Field by field: the report's structs hold padding (after a bool, before a double), which a
// copy of their bytes would send as whatever the memory held.
void put_filter(ByteWriter& w, const FilterReport& f) {
  w.put(static_cast<std::uint8_t>(f.choice.mode));
  w.put(static_cast<std::uint8_t>(f.choice.adapt));
  w.put(f.choice.window);
  w.put(static_cast<std::uint8_t>(f.cutoffs.diagonals));
  for (const double v : {f.cutoffs.row_cut_pct, f.cutoffs.col_cut_pct, f.cutoffs.ctrl_col_pct,
                         f.scale, f.median_slope_pct, f.heights.quantum, f.heights.tolerance,
                         f.local_lowest, f.local_highest})
    w.put(v);
}

void get_filter(ByteReader& r, FilterReport& f) {
  std::uint8_t mode = 0, adapt = 0, diagonals = 0;
  r.get(mode);
  r.get(adapt);
  r.get(f.choice.window);
  r.get(diagonals);
  if (mode > 1 || adapt > 1 || diagonals > 1)
    throw Error("these bytes are not a filter's report of Terrain Sketch: a choice out of range");
  f.choice.mode = static_cast<FilterMode>(mode);
  f.choice.adapt = static_cast<Adaptivity>(adapt);
  f.cutoffs.diagonals = diagonals == 1;
  for (double* v : {&f.cutoffs.row_cut_pct, &f.cutoffs.col_cut_pct, &f.cutoffs.ctrl_col_pct,
                    &f.scale, &f.median_slope_pct, &f.heights.quantum, &f.heights.tolerance,
                    &f.local_lowest, &f.local_highest})
    r.get(*v);
}

void get_class(ByteReader& r, StrokeClass& cls) {
  r.get(cls);
  if (cls != StrokeClass::factual && cls != StrokeClass::formulated)
    throw Error("these bytes are not a band's sketch of Terrain Sketch: a stroke of no class");
}

// A stroke still to be drawn (a piece) goes with its whole chain, from which the drawing works;
// an exact stroke, or one its band has drawn, with its first cell, which places it in the run's
// order. The writer needs no more.
void put_stroke(ByteWriter& w, const Stroke& s) {
  w.put(s.cls);
  w.put(s.points);
  w.put(s.vertices);
  if (s.vertices.empty()) {
    w.put(s.chain.front());
  } else {
    w.put(s.chain);
  }
  w.put(s.weights);
  w.put(s.cells);
  for (const double v : {s.length, s.mean_slope_pct, s.mean_row_slope_pct, s.mean_depth_m,
                         s.max_depth_m, s.mean_dist, s.mean_z})
    w.put(v);
}

void get_stroke(ByteReader& r, Stroke& s) {
  get_class(r, s.cls);
  r.get(s.points);
  r.get(s.vertices);
  if (s.vertices.empty()) {
    s.chain.resize(1);
    r.get(s.chain.front());
  } else {
    r.get(s.chain);
  }
  r.get(s.weights);
  r.get(s.cells);
  for (double* v : {&s.length, &s.mean_slope_pct, &s.mean_row_slope_pct, &s.mean_depth_m,
                    &s.max_depth_m, &s.mean_dist, &s.mean_z})
    r.get(*v);
}

void get_drawn_groups(ByteReader& r, std::vector<DrawnGroup>& groups) {
  std::uint64_t count = 0;
  r.get(count);
  for (std::uint64_t g = 0; g < count; ++g) {
    groups.emplace_back();
    DrawnGroup& group = groups.back();
    get_class(r, group.cls);
    r.get(group.key);
    std::uint64_t strokes = 0;
    r.get(strokes);
    for (std::uint64_t k = 0; k < strokes; ++k) {
      group.strokes.emplace_back();
      get_stroke(r, group.strokes.back());
    }
  }
}

// A value as bytes that begin with the mark of its kind, and back.
template <typename T, typename Put>
std::string marked_bytes(std::uint32_t mark, const T& value, Put put) {
  ByteWriter w;
  w.put(mark);
  put(w, value);
  return w.take();
}

template <typename T, typename Get>
T from_marked_bytes(const std::string& bytes, const char* what, std::uint32_t mark, Get get) {
  ByteReader r(bytes, what);
  r.expect(mark);
  T value;
  get(r, value);
  r.finish();
  return value;
}

}  // namespace

std::string band_bytes(const BandSketch& band) {
  ByteWriter w;
  w.put(kBandMagic);
  w.put(static_cast<std::uint64_t>(band.first));
  w.put(static_cast<std::uint64_t>(band.count));
  w.put(band.stats);
  put_filter(w, band.filter);
  put_orders(w, band.in);
  put_orders(w, band.out);
  w.put(band.deciding.factual);
  w.put(band.deciding.formulated);
  w.put(static_cast<std::uint64_t>(band.strokes.size()));
  for (const Stroke& stroke : band.strokes) put_stroke(w, stroke);
  w.put(band.keys);
  w.put(static_cast<std::uint64_t>(band.drawn.size()));
  for (const DrawnGroup& group : band.drawn) {
    w.put(group.cls);
    w.put(group.key);
    w.put(static_cast<std::uint64_t>(group.strokes.size()));
    for (const Stroke& stroke : group.strokes) put_stroke(w, stroke);
  }
  w.put(static_cast<std::uint64_t>(band.pieces.size()));
  for (const BandPiece& piece : band.pieces) {
    w.put(piece.cls);
    w.put(piece.in);
    w.put(piece.out);
    w.put(piece.cells);
  }
  return w.take();
}

BandSketch band_from_bytes(std::string_view bytes) {
  ByteReader r(bytes, "a band's sketch");
  r.expect(kBandMagic);
  BandSketch band;
  std::uint64_t first = 0, count = 0, strokes = 0, pieces = 0;
  r.get(first);
  r.get(count);
  band.first = static_cast<std::size_t>(first);
  band.count = static_cast<std::size_t>(count);
  r.get(band.stats);
  get_filter(r, band.filter);
  get_orders(r, band.in);
  get_orders(r, band.out);
  r.get(band.deciding.factual);
  r.get(band.deciding.formulated);
  r.get(strokes);
  for (std::uint64_t k = 0; k < strokes; ++k) {
    band.strokes.emplace_back();
    get_stroke(r, band.strokes.back());
  }
  r.get(band.keys);
  get_drawn_groups(r, band.drawn);
  r.get(pieces);
  for (std::uint64_t k = 0; k < pieces; ++k) {
    band.pieces.emplace_back();
    BandPiece& piece = band.pieces.back();
    get_class(r, piece.cls);
    r.get(piece.in);
    r.get(piece.out);
    r.get(piece.cells);
  }
  r.finish();
  return band;
}

std::string orders_bytes(const BandOrders& orders) {
  return marked_bytes(kOrderMagic, orders, put_orders);
}

BandOrders orders_from_bytes(const std::string& bytes) {
  return from_marked_bytes<BandOrders>(bytes, "an order of chains", kOrderMagic, get_orders);
}

std::string filter_report_bytes(const FilterReport& report) {
  return marked_bytes(kFilterMagic, report, put_filter);
}

FilterReport filter_report_from_bytes(const std::string& bytes) {
  return from_marked_bytes<FilterReport>(bytes, "a filter's report", kFilterMagic, get_filter);
}

}  // namespace tsk
