// A run cut into bands of profiles and stitched (core/method/bands.h) against the same run made
// whole by sketch_silhouettes: the same strokes, exact and drawn, point for point, weight for
// weight and attribute for attribute, in the same order, and the same statistics, on real DEMs,
// cardinal and resampled views, bands as narrow as one profile, halos too short to guess the
// chains' order (so bands are sketched again, or kept where no join depended on the guess) and
// long enough, and the bands handed over as bytes. Drawn strokes are drawn partly by the bands (the
// groups far from their edges) and partly by the stitcher.
#include <cstring>
#include <new>

#include "catch_compat.h"
#include "core/drawn/drawn_strokes.h"
#include "core/method/bands.h"
#include "io/read/dem_reader.h"

using namespace tsk;

namespace {

const std::string kData = TSK_TEST_DATA;

ResolvedParams run_params(const io::DemFile& dem, double azimuth, FilterMode mode,
                          StrokeMode strokes = StrokeMode::exact) {
  SilhouetteParams p;
  p.view.azimuth_deg = azimuth;
  p.adaptive.mode = mode;
  p.strokes.mode = strokes;
  p.threads = 2;
  return adapt_filter(p, dem.info().grid, dem.source().read);
}

struct Stitched {
  SilhouetteResult result;
  std::size_t bands = 0, sketched_again = 0;
  // Bands linked from a guess that differs from the true order but keeps its deciding pairs.
  std::size_t kept_from_guess = 0;
  // Drawn strokes: those the bands drew, and the pieces they left to the stitcher.
  std::size_t drawn_by_bands = 0, pieces_left = 0;
};

// Sketches the bands of `width` profiles apart, as machines would, then stitches them in order,
// sketching a band again from the true order when its guess was wrong. Each band goes through
// bytes.
Stitched in_bands(const io::DemFile& dem, const ResolvedParams& params, std::size_t width,
                  std::size_t halo) {
  const OrientedFrame frame = make_frame(dem.info().grid, params->view.azimuth_deg);
  std::vector<std::string> sketches;
  Stitched out;
  for (std::size_t first = 0; first < frame.profiles; first += width) {
    BandSpec spec{first, std::min(width, frame.profiles - first), std::nullopt, halo};
    const BandSketch band = sketch_band(dem.source(), params, spec);
    for (const DrawnGroup& group : band.drawn) out.drawn_by_bands += group.strokes.size();
    out.pieces_left += band.strokes.size();
    sketches.push_back(band_bytes(band));
  }
  out.bands = sketches.size();
  std::optional<DrawingSetup> drawing;
  if (params->strokes.drawn())
    drawing = drawing_setup(frame, dem.info().geotransform, params.params(), 0.0);
  BandStitcher stitcher(params, {}, drawing);
  const auto again = [&](std::size_t first, std::size_t count, const BandOrders& order) {
    ++out.sketched_again;
    const BandOrders sent = orders_from_bytes(orders_bytes(order));
    return sketch_band(dem.source(), params, BandSpec{first, count, sent, 0});
  };
  // add() throws if the band sketched again does not follow either.
  for (const std::string& bytes : sketches) {
    BandSketch band = band_from_bytes(bytes);
    if (band.first > 0 && band.in != stitcher.order() && stitcher.follows(band))
      ++out.kept_from_guess;
    stitcher.add(std::move(band), again);
  }
  out.result = stitcher.finish(frame.profiles);
  return out;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void require_same_strokes(const SilhouetteResult& whole, const SilhouetteResult& stitched) {
  REQUIRE(stitched.strokes.size() == whole.strokes.size());
  for (std::size_t k = 0; k < whole.strokes.size(); ++k) {
    const Stroke& a = whole.strokes[k];
    const Stroke& b = stitched.strokes[k];
    INFO("stroke " << k);
    REQUIRE(a.cls == b.cls);
    REQUIRE(a.cells == b.cells);
    REQUIRE(a.points.size() == b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      REQUIRE(same_bits(a.points[i].x, b.points[i].x));
      REQUIRE(same_bits(a.points[i].y, b.points[i].y));
    }
    REQUIRE(a.weights.size() == b.weights.size());
    for (std::size_t i = 0; i < a.weights.size(); ++i)
      REQUIRE(same_bits(a.weights[i], b.weights[i]));
    for (const StrokeRealField& field : stroke_real_fields())
      REQUIRE(same_bits(a.*(field.member), b.*(field.member)));
  }
  const StageStats& s = whole.stats;
  const StageStats& t = stitched.stats;
  CHECK(t.valid == s.valid);
  CHECK(t.hidden == s.hidden);
  CHECK(t.occluding == s.occluding);
  CHECK(t.candidate == s.candidate);
  CHECK(t.filtered == s.filtered);
  CHECK(t.thinned == s.thinned);
  CHECK(t.generalised == s.generalised);
  CHECK(t.factual_strokes == s.factual_strokes);
  CHECK(t.formulated_strokes == s.formulated_strokes);
}

}  // namespace

TEST_CASE("bands stitched give the strokes of one run", "[bands]") {
  struct Case {
    const char* file;
    double azimuth;
    FilterMode mode;
    StrokeMode strokes;
  };
  const Case cases[] = {{"jacksboro_utm16n.tif", 90, FilterMode::fixed, StrokeMode::exact},
                        {"jacksboro_utm16n.tif", 200, FilterMode::adaptive, StrokeMode::exact},
                        {"gorillas_utm32n.tif", 270, FilterMode::adaptive, StrokeMode::exact},
                        {"volcano.tif", 0, FilterMode::fixed, StrokeMode::exact},
                        {"jacksboro_utm16n.tif", 90, FilterMode::adaptive, StrokeMode::drawn},
                        {"gorillas_utm32n.tif", 135, FilterMode::adaptive, StrokeMode::drawn}};
  for (const Case& c : cases) {
    const io::DemFile dem(kData + "/" + c.file, io::DemOptions());
    const ResolvedParams params = run_params(dem, c.azimuth, c.mode, c.strokes);
    const SilhouetteResult whole = sketch_silhouettes(dem.source(), params.params());
    REQUIRE(whole.stats.formulated_strokes > 0);
    for (const std::size_t width : {1, 7, 40, 100000}) {
      for (const std::size_t halo : {1, 64}) {
        INFO(c.file << " from " << c.azimuth << (c.strokes == StrokeMode::drawn ? ", drawn" : "")
                    << ", bands of " << width << ", halo " << halo);
        const Stitched stitched = in_bands(dem, params, width, halo);
        require_same_strokes(whole, stitched.result);
        // A halo of one profile guesses wrong somewhere among many bands, so the repair is tested,
        // and so are bands kept although their guess was wrong, as no join depended on it.
        if (halo == 1 && width <= 7) CHECK(stitched.sketched_again > 0);
        if (halo == 1 && width <= 7) CHECK(stitched.kept_from_guess > 0);
        if (c.strokes != StrokeMode::drawn) continue;
        // A band draws the groups no other band can reach, and leaves the rest to the stitcher:
        // one band of the whole grid draws every one, bands of a profile none.
        if (width == 100000) CHECK(stitched.pieces_left == 0);
        if (width == 40) CHECK((stitched.drawn_by_bands > 0 && stitched.pieces_left > 0));
        if (width == 1) CHECK(stitched.drawn_by_bands == 0);
      }
    }
  }
}

TEST_CASE("bands refuse what they cannot stitch", "[bands]") {
  const io::DemFile dem(kData + "/jacksboro_utm16n.tif", io::DemOptions());
  const ResolvedParams params = run_params(dem, 90, FilterMode::fixed);
  BandSketch first = sketch_band(dem.source(), params, BandSpec{0, 50, std::nullopt, 8});
  BandSketch third = sketch_band(dem.source(), params, BandSpec{100, 50, std::nullopt, 8});
  BandStitcher stitcher(params);
  CHECK_FALSE(stitcher.follows(third));
  CHECK_THROWS_WITH(stitcher.add(std::move(third)), Catch::Contains("does not follow"));
  stitcher.add(std::move(first));
  CHECK_THROWS_WITH(stitcher.finish(1000), Catch::Contains("last profile"));
  std::string bytes = band_bytes(sketch_band(dem.source(), params, BandSpec{0, 5, {}, 1}));
  CHECK_THROWS_WITH(band_from_bytes(bytes.substr(0, bytes.size() - 3)),
                    Catch::Contains("not a band's sketch"));
  CHECK_THROWS_WITH(orders_from_bytes(bytes), Catch::Contains("not an order"));
  CHECK_THROWS_WITH(sketch_band(dem.source(), params, BandSpec{400, 100, {}, 1}),
                    Catch::Contains("does not lie in the grid"));
}

TEST_CASE("a filter's report goes out as its values only, and comes back whole", "[bands]") {
  // Two reports alike, made in memory that held different bytes: the padding of their structs
  // (after the bool of the cut-offs) must not reach the bytes a worker sends.
  alignas(FilterReport) unsigned char zeros[sizeof(FilterReport)], ones[sizeof(FilterReport)];
  std::memset(zeros, 0x00, sizeof zeros);
  std::memset(ones, 0xff, sizeof ones);
  auto* a = new (zeros) FilterReport;
  auto* b = new (ones) FilterReport;
  for (FilterReport* r : {a, b}) {
    r->choice.mode = FilterMode::adaptive;
    r->cutoffs.diagonals = false;
    r->scale = 0.275;
    r->median_slope_pct = 6.6;
    r->heights = {0.01, 0.005};
  }
  const std::string bytes = filter_report_bytes(*a);
  CHECK(bytes == filter_report_bytes(*b));
  const FilterReport back = filter_report_from_bytes(bytes);
  CHECK(back.choice.mode == FilterMode::adaptive);
  CHECK(back.choice.adapt == a->choice.adapt);
  CHECK(back.choice.window == a->choice.window);
  CHECK_FALSE(back.cutoffs.diagonals);
  CHECK(back.cutoffs.row_cut_pct == a->cutoffs.row_cut_pct);
  CHECK(back.cutoffs.ctrl_col_pct == a->cutoffs.ctrl_col_pct);
  CHECK(back.scale == 0.275);
  CHECK(back.heights.tolerance == 0.005);
  CHECK(back.local_highest == a->local_highest);
  // A choice out of range is refused, not read into an enum or a bool.
  std::string bad = bytes;
  bad[4] = 7;  // the filter's mode, after the mark
  CHECK_THROWS_WITH(filter_report_from_bytes(bad), Catch::Contains("out of range"));
  CHECK_THROWS_WITH(filter_report_from_bytes(bytes + "x"), Catch::Contains("not a filter's"));
  a->~FilterReport();
  b->~FilterReport();
}
