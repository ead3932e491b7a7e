// The adaptive slope filter: its survey of the DEM's slopes, its scale, its height tolerance and
// its local adaptivity, against brute force and invariances.
#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include "catch_compat.h"
#include "core/method/adaptive_filter.h"
#include "core/method/choice_names.h"
#include "core/method/slope_scale_map.h"
#include "resampled_silhouettes.h"
#include "test_support.h"

using namespace tsk;

namespace {

// A DEM held in memory, read window by window as the front ends read files.
DemSource memory_source(const HeightGrid& dem, double cell) {
  return {DemGrid{dem.rows(), dem.cols(), cell, cell}, GeoTransform{},
          [&dem](const DemWindow& w, float* out) {
            for (std::size_t r = 0; r < w.rows; ++r)
              std::copy_n(dem.row(w.row0 + r) + w.col0, w.cols, out + r * w.cols);
          }};
}

// Rolling terrain with slopes of many sizes: two bumps on a tilted plane.
HeightGrid rolling(std::size_t rows, std::size_t cols, double scale = 1.0) {
  HeightGrid z(rows, cols);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      const double x = static_cast<double>(c), y = static_cast<double>(r);
      const double h = 3.0 * x + 40.0 * std::sin(x / 9.0) * std::cos(y / 5.0) +
                       25.0 * std::exp(-((x - 60) * (x - 60) + (y - 50) * (y - 50)) / 300.0);
      z(r, c) = static_cast<float>(scale * h);
    }
  }
  return z;
}

// The median of every cell's forward-difference slope (percent), flat cells left out: the
// survey's answer worked out by brute force.
double brute_median_slope(const HeightGrid& z, double cell, double tolerance) {
  std::vector<double> slopes;
  for (std::size_t r = 0; r + 1 < z.rows(); ++r) {
    for (std::size_t c = 0; c + 1 < z.cols(); ++c) {
      const double east = double{z(r, c + 1)} - z(r, c);
      const double south = double{z(r + 1, c)} - z(r, c);
      if (std::fabs(east) <= tolerance && std::fabs(south) <= tolerance) continue;
      slopes.push_back(100.0 * std::sqrt(east * east + south * south) / cell);
    }
  }
  std::nth_element(slopes.begin(), slopes.begin() + slopes.size() / 2, slopes.end());
  return slopes[slopes.size() / 2];
}

SilhouetteParams adaptive() {
  SilhouetteParams p;
  p.adaptive.mode = FilterMode::adaptive;
  return p;
}

}  // namespace

TEST_CASE("the survey's median slope is the brute-force median within a bin", "[adaptive]") {
  const HeightGrid z = rolling(120, 140);
  const DemSource dem = memory_source(z, 10.0);
  const SlopeSurvey survey = survey_slopes(z.rows(), z.cols(), 10.0, 10.0, dem.read);
  const double brute = brute_median_slope(z, 10.0, survey.heights.tolerance);
  // Bins are an eighth of an octave wide (9 %); the median is interpolated within its bin.
  CHECK(survey.median_slope_pct == Approx(brute).epsilon(0.09));
  CHECK(survey.cells == 119u * 139u);
}

TEST_CASE("survey windows lie in their parts of the DEM and on block edges where they fit",
          "[adaptive]") {
  for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{8000, 8000},
                                   {1700, 1400},
                                   {2100, 30000},
                                   {40000, 1201}}) {
    CAPTURE(rows, cols);
    const std::vector<DemWindow> windows = survey_windows(rows, cols);
    REQUIRE(windows.size() == 64);
    std::size_t on_block_edges = 0;
    for (std::size_t k = 0; k < windows.size(); ++k) {
      const DemWindow& w = windows[k];
      const std::size_t a = k / 8, b = k % 8;
      // Inside its eighth of the rows and of the columns (a part narrower than a window: centred
      // on it, a cell beyond it either side), and inside the DEM.
      CHECK(w.row0 + 1 >= a * rows / 8);
      CHECK(w.row0 + w.rows <= std::min(rows, (a + 1) * rows / 8 + 1));
      CHECK(w.col0 + 1 >= b * cols / 8);
      CHECK(w.col0 + w.cols <= std::min(cols, (b + 1) * cols / 8 + 1));
      // Within one block of 512 (so of 256) each way wherever a part is long enough for it.
      const bool fits = w.row0 / 512 == (w.row0 + w.rows - 1) / 512 &&
                        w.col0 / 512 == (w.col0 + w.cols - 1) / 512;
      on_block_edges += fits && w.row0 % 512 == 0 && w.col0 % 512 == 0;
    }
    if (rows >= 8000 && cols >= 8000) CHECK(on_block_edges == 64);
  }
}

TEST_CASE("the survey's window count is the number of windows it lists", "[adaptive]") {
  // Sizes about the whole-DEM limit (2^21 cells) and with fewer rows or columns than the lattice.
  for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{1, 1},
                                   {1448, 1448},
                                   {1449, 1449},
                                   {2048, 1024},
                                   {2048, 1025},
                                   {3, 1000000},
                                   {1000000, 5},
                                   {8000, 8000}}) {
    CAPTURE(rows, cols);
    CHECK(survey_window_count(rows, cols) == survey_windows(rows, cols).size());
  }
}

TEST_CASE("with two readers each survey window is read by one of them, with one by it",
          "[adaptive]") {
  std::size_t second_reads = 0;
  for (std::size_t k = 0; k < 64; ++k) {
    CAPTURE(k);
    CHECK(reader_takes(k, true, false) != reader_takes(k, true, true));
    CHECK(reader_takes(k, false, false));
    second_reads += reader_takes(k, true, true);
  }
  CHECK(second_reads == 32);  // the reads halved between the two
}

TEST_CASE("a survey made in parts, through bytes and in any order, is the survey", "[adaptive]") {
  // 64 windows on a DEM over two million cells; float heights, then whole metres.
  HeightGrid z = rolling(1700, 1400);
  for (const bool quantised : {false, true}) {
    CAPTURE(quantised);
    if (quantised)
      for (std::size_t r = 0; r < z.rows(); ++r)
        for (std::size_t c = 0; c < z.cols(); ++c) z.row(r)[c] = std::round(z.row(r)[c]);
    const DemSource dem = memory_source(z, 7.5);
    const SlopeSurvey whole = survey_slopes(z.rows(), z.cols(), 7.5, 7.5, dem.read);
    const std::vector<DemWindow> windows = survey_windows(z.rows(), z.cols());
    REQUIRE(windows.size() == 64);
    // Five machines, each some of the windows (every third, fifth, ... in turn).
    std::vector<std::vector<DemWindow>> parts(5);
    for (std::size_t k = 0; k < windows.size(); ++k) parts[(k * 7) % 5].push_back(windows[k]);
    const auto read = [&](const DemWindow& w) {
      std::vector<float> heights(w.rows * w.cols);
      dem.read(w, heights.data());
      return heights;
    };
    HeightStepPart steps;
    for (std::size_t m = parts.size(); m-- > 0;) {
      HeightStepPart part;
      for (const DemWindow& w : parts[m]) part.add(read(w).data(), w.rows * w.cols);
      steps.merge(SurveyBytes::height_step(SurveyBytes::of(part)));
    }
    const HeightStep step = steps.step();
    CHECK(step.quantum == whole.heights.quantum);
    CHECK(step.tolerance == whole.heights.tolerance);
    CHECK(step.quantum == (quantised ? 1.0 : 0.0));
    SlopePart slopes;
    for (const std::vector<DemWindow>& machine : parts) {
      SlopePart part;
      for (const DemWindow& w : machine) part.add(read(w).data(), w, 7.5, 7.5, step.tolerance);
      slopes.merge(SurveyBytes::slopes(SurveyBytes::of(part)));
    }
    const SlopeSurvey merged = slopes.survey(step);
    CHECK(merged.median_slope_pct == whole.median_slope_pct);
    CHECK(merged.cells == whole.cells);
    CHECK(merged.flat_cells == whole.flat_cells);
    CHECK(merged.cells > 1900000u);
  }
  // Bytes of one kind are not taken for the other.
  CHECK_THROWS_AS(SurveyBytes::slopes(SurveyBytes::of(HeightStepPart())), Error);
  CHECK_THROWS_AS(SurveyBytes::height_step(SurveyBytes::of(SlopePart())), Error);
}

TEST_CASE("a survey on any number of threads counts the slopes of one pass", "[adaptive]") {
  // One window (the whole DEM) of 701 rows: six bands of rows, measured on 1 to 5 threads.
  const HeightGrid z = rolling(701, 90);
  const DemSource dem = memory_source(z, 5.0);
  HeightStepPart step;
  step.add(z.data(), z.size());
  SlopePart one_pass;
  one_pass.add(z.data(), {0, 0, z.rows(), z.cols()}, 5.0, 5.0, step.step().tolerance);
  const SlopeSurvey expected = one_pass.survey(step.step());
  REQUIRE(expected.cells == 700u * 89u);
  for (const unsigned threads : {1u, 2u, 3u, 5u}) {
    CAPTURE(threads);
    const SlopeSurvey survey = survey_slopes(z.rows(), z.cols(), 5.0, 5.0, dem.read, threads);
    CHECK(survey.median_slope_pct == expected.median_slope_pct);
    CHECK(survey.cells == expected.cells);
    CHECK(survey.flat_cells == expected.flat_cells);
  }
}

TEST_CASE("a survey read through two readers, half on a thread of its own, is the survey of one",
          "[adaptive]") {
  const HeightGrid z = rolling(1700, 1400);  // over two million cells: 64 windows
  const DemSource dem = memory_source(z, 10.0);
  const std::vector<DemWindow> windows = survey_windows(z.rows(), z.cols());
  REQUIRE(windows.size() == 64);
  const auto index_of = [&](const DemWindow& w) {
    for (std::size_t k = 0; k < windows.size(); ++k)
      if (windows[k].row0 == w.row0 && windows[k].col0 == w.col0) return k;
    FAIL("a window the survey does not read");
    return windows.size();
  };
  std::vector<std::size_t> first, second;
  std::thread::id second_thread;
  std::mutex noting;
  const WindowReader read = [&](const DemWindow& w, float* out) {
    dem.read(w, out);
    const std::lock_guard<std::mutex> lock(noting);
    first.push_back(index_of(w));
  };
  const WindowReader alongside = [&](const DemWindow& w, float* out) {
    dem.read(w, out);
    const std::lock_guard<std::mutex> lock(noting);
    second.push_back(index_of(w));
    second_thread = std::this_thread::get_id();
  };
  const SlopeSurvey one = survey_slopes(z.rows(), z.cols(), 10.0, 10.0, dem.read, 2);
  const SlopeSurvey two = survey_slopes(z.rows(), z.cols(), 10.0, 10.0, read, 2, alongside);
  CHECK(two.median_slope_pct == one.median_slope_pct);
  CHECK(two.cells == one.cells);
  CHECK(two.flat_cells == one.flat_cells);
  CHECK(two.heights.tolerance == one.heights.tolerance);
  // Every other pair of windows through the second reader, on a thread of its own.
  REQUIRE(first.size() == 32);
  REQUIRE(second.size() == 32);
  for (const std::size_t k : first) CHECK_FALSE(read_alongside(k));
  for (const std::size_t k : second) CHECK(read_alongside(k));
  CHECK(second_thread != std::this_thread::get_id());
  // On one thread the second reader is not used; its failure is the survey's.
  first.clear(), second.clear();
  survey_slopes(z.rows(), z.cols(), 10.0, 10.0, read, 1, alongside);
  CHECK(first.size() == 64);
  CHECK(second.empty());
  const WindowReader failing = [](const DemWindow&, float*) { throw Error("disk gone"); };
  REQUIRE_THROWS_WITH(survey_slopes(z.rows(), z.cols(), 10.0, 10.0, read, 2, failing), "disk gone");
  REQUIRE_THROWS_WITH(survey_slopes(z.rows(), z.cols(), 10.0, 10.0, failing, 2, alongside),
                      "disk gone");
}

TEST_CASE("the height step is found from the heights", "[adaptive]") {
  const std::vector<float> metres = {12, 15, NAN, 300, -4};
  CHECK(height_step(metres.data(), metres.size()).quantum == 1.0);
  CHECK(height_step(metres.data(), metres.size()).tolerance == 0.5);
  const std::vector<float> decimetres = {12.3f, 15.1f, 300.7f, -4.2f};
  CHECK(height_step(decimetres.data(), decimetres.size()).quantum == 0.1);
  const std::vector<float> floats = {12.345678f, 1000.1234f, 3.3333333f};
  const HeightStep step = height_step(floats.data(), floats.size());
  CHECK(step.quantum == 0.0);
  CHECK(step.tolerance == Approx(1e-6 * 1000.1234));
}

TEST_CASE("float's fill values change neither the height step nor the survey's median",
          "[adaptive][robustness]") {
  // An undeclared fill value made every step between real heights "flat" (a tolerance of a
  // millionth of 3.4e38): the median was the histogram's top and the filter kept nothing.
  const std::vector<float> floats = {12.345678f, 1000.1234f, 3.3333333f, 3.4028235e38f, -1e30f};
  CHECK(height_step(floats.data(), floats.size()).tolerance == Approx(1e-6 * 1000.1234));
  const std::vector<float> metres = {12, 15, -3.4028235e38f, 300};
  CHECK(height_step(metres.data(), metres.size()).tolerance == 0.5);
  for (const float fill : {3.4028235e38f, -3.4028235e38f, 1e30f, -1e30f}) {
    CAPTURE(fill);
    HeightGrid holed = rolling(120, 140), filled = holed;
    for (std::size_t r = 30; r < 45; ++r) {
      for (std::size_t c = 70; c < 85; ++c) holed(r, c) = NAN, filled(r, c) = fill;
    }
    const DemSource holed_dem = memory_source(holed, 10.0),
                    filled_dem = memory_source(filled, 10.0);
    const SlopeSurvey without =
        survey_slopes(holed.rows(), holed.cols(), 10.0, 10.0, holed_dem.read);
    const SlopeSurvey with =
        survey_slopes(filled.rows(), filled.cols(), 10.0, 10.0, filled_dem.read);
    // Fill values are nodata to the survey: the same slopes are counted as around a hole.
    CHECK(with.heights.tolerance == without.heights.tolerance);
    CHECK(with.median_slope_pct == without.median_slope_pct);
    CHECK(with.cells == without.cells);
    CHECK(with.flat_cells == without.flat_cells);
    CHECK(without.cells < 119u * 139u);
  }
}

TEST_CASE("the scale follows the median slope and is held within its bounds", "[adaptive]") {
  CHECK(filter_scale(kReferenceSlopePct) == 1.0);
  CHECK(filter_scale(kReferenceSlopePct / 2) == 0.5);
  CHECK(filter_scale(0.01) == kLowestScale);
  CHECK(filter_scale(1e6) == kHighestScale);
  CHECK(filter_scale(std::nan("")) == kLowestScale);
}

TEST_CASE("a fixed filter is left as it is", "[adaptive]") {
  const HeightGrid z = rolling(60, 70);
  const DemSource dem = memory_source(z, 10.0);
  SilhouetteParams fixed;
  fixed.filter.row_cut_pct = 30;
  const ResolvedParams run = adapt_filter(fixed, dem.grid, dem.read);
  CHECK(run->filter.row_cut_pct == 30);
  CHECK(run->height_tolerance == 0.0);
  CHECK(run->local_scale == nullptr);
  CHECK(run.filter().scale == 1.0);
  CHECK(run.filter().choice.mode == FilterMode::fixed);
}

TEST_CASE("an adaptive filter cannot run unresolved, and reports what it ran", "[adaptive]") {
  const HeightGrid z = rolling(60, 70);
  const DemSource dem = memory_source(z, 10.0);
  SilhouetteParams asked;
  asked.adaptive.mode = FilterMode::adaptive;
  // Taken as fixed, the run would apply the thesis's cut-offs while reporting "adaptive".
  CHECK_THROWS_AS(ResolvedParams(asked), Error);
  CHECK_THROWS_AS(adapt_filter(asked, dem.grid, WindowReader()), Error);
  const ResolvedParams run = adapt_filter(asked, dem.grid, dem.read);
  const SilhouetteResult result = run_silhouettes(z, make_frame(dem.grid, 90.0), {}, run);
  // The stages took the scaled cut-offs, and the result says so: the report is the resolving's.
  CHECK(run->filter.row_cut_pct == Approx(asked.filter.row_cut_pct * run.filter().scale));
  CHECK(result.filter.choice.mode == FilterMode::adaptive);
  CHECK(result.filter.scale == run.filter().scale);
  CHECK(result.filter.cutoffs.row_cut_pct == run->filter.row_cut_pct);
  CHECK(result.filter.scale != 1.0);
}

TEST_CASE("doubling the relief and halving the exaggeration gives the same sketch", "[adaptive]") {
  // Relief invariance: the c-set sees ve * gc, the same for both; the adaptive cut-offs double
  // with the slopes, so the filter accepts the same cells. The fixed filter does not.
  // A cone of 10 % slopes: the fixed filter removes its back's gentle cells, the adaptive one,
  // scaled to its gentle slopes, keeps them.
  const HeightGrid z = make_cone(100, 120, 10.0, 100.0, 0.1);
  const HeightGrid doubled = make_cone(100, 120, 10.0, 200.0, 0.2);
  SilhouetteParams p = adaptive(), q = adaptive();
  q.view.ve = p.view.ve / 2;
  const SilhouetteResult a = sketch_silhouettes(memory_source(z, 10.0), p);
  const SilhouetteResult b = sketch_silhouettes(memory_source(doubled, 10.0), q);
  CHECK(b.filter.scale == Approx(2 * a.filter.scale));
  CHECK(a.stats.candidate == b.stats.candidate);
  CHECK(a.stats.filtered == b.stats.filtered);
  CHECK(a.stats.formulated_strokes == b.stats.formulated_strokes);
  CHECK(a.stats.filtered > 0);
  p.adaptive.mode = q.adaptive.mode = FilterMode::fixed;
  const SilhouetteResult c = sketch_silhouettes(memory_source(z, 10.0), p);
  const SilhouetteResult d = sketch_silhouettes(memory_source(doubled, 10.0), q);
  CHECK(c.stats.filtered != d.stats.filtered);
}

TEST_CASE("integer heights give the same c-set a millionth of a degree off a cardinal view",
          "[adaptive]") {
  // Terraces of whole metres: a resampled flat cell's step is a tiny number, not 0, and SPEC's
  // strict test flips on it; the adaptive filter's tolerance of half a metre does not.
  HeightGrid z = rolling(90, 110, 0.3);
  for (std::size_t k = 0; k < z.size(); ++k) z.data()[k] = std::round(z.data()[k]);
  auto cset = [&](FilterMode mode, double azimuth) {
    SilhouetteParams p;
    p.adaptive.mode = mode;
    p.view.azimuth_deg = azimuth;
    const SilhouetteResult r = sketch_silhouettes(memory_source(z, 10.0), p);
    return r.stats.pct(r.stats.candidate);
  };
  for (double azimuth : {90.0, 0.0}) {
    CAPTURE(azimuth);
    CHECK(std::fabs(cset(FilterMode::adaptive, azimuth) -
                    cset(FilterMode::adaptive, azimuth + 1e-6)) < 0.5);
    CHECK(std::fabs(cset(FilterMode::fixed, azimuth) - cset(FilterMode::fixed, azimuth + 1e-6)) >
          0.5);
  }
}

TEST_CASE("local adaptivity keeps a plain's breaks of slope beside mountains", "[adaptive]") {
  // West half: a plain with gentle steps; east half: steep mountains.
  HeightGrid z(120, 240);
  for (std::size_t r = 0; r < z.rows(); ++r) {
    for (std::size_t c = 0; c < z.cols(); ++c) {
      const double x = static_cast<double>(c), y = static_cast<double>(r);
      const double plain = 0.4 * std::sin(x / 5.0) * std::cos(y / 7.0) - 0.02 * x;
      const double mountains = c < 120 ? 0.0 : 60.0 * std::sin(x / 6.0) * std::sin(y / 8.0);
      z(r, c) = static_cast<float>(100.0 + plain + mountains);
    }
  }
  SilhouetteParams whole = adaptive(), local = adaptive();
  local.adaptive.adapt = Adaptivity::local;
  local.adaptive.window = 40;
  const DemSource dem = memory_source(z, 10.0);
  const SilhouetteResult w =
      run_silhouettes(z, make_frame(dem.grid, 90.0), {}, adapt_filter(whole, dem.grid, dem.read));
  const ResolvedParams run = adapt_filter(local, dem.grid, dem.read);
  const FilterReport& report = run.filter();
  REQUIRE(run->local_scale);
  CHECK(report.local_lowest < report.scale);
  CHECK(report.local_highest > report.scale);
  const SilhouetteResult l = run_silhouettes(z, make_frame(dem.grid, 90.0), {}, run);
  auto plain_fset = [](const SilhouetteResult& r) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < r.flags.rows(); ++p)
      for (std::size_t i = 0; i < 100; ++i) n += (r.flags(p, i) & cell::filtered) != 0;
    return n;
  };
  CHECK(plain_fset(l) > 2 * plain_fset(w));
}

TEST_CASE("the choices' names and order are pinned: saved models keep their meaning", "[params]") {
  // QGIS saves an enum parameter's position: a model saved with STROKES=1 asked for exact strokes
  // and must go on getting them. The command line's names are the same tables'.
  CHECK(choice_at(kStrokeModeNames, 0, "strokes") == StrokeMode::drawn);
  CHECK(choice_at(kStrokeModeNames, 1, "strokes") == StrokeMode::exact);
  CHECK(choice_at(kFilterModeNames, 0, "filter") == FilterMode::adaptive);
  CHECK(choice_at(kFilterModeNames, 1, "filter") == FilterMode::fixed);
  CHECK(choice_at(kAdaptivityNames, 1, "adapt") == Adaptivity::local);
  CHECK(choice_at(kGeometryNames, 1, "geometry") == Geometry::oblique);
  CHECK(choice_at(kPlacementNames, 1, "placement") == Placement::near_and_far);
  CHECK_THROWS_WITH(choice_at(kStrokeModeNames, 2, "STROKES"), "STROKES has no option 2");
  CHECK(parse_stroke_mode("exact") == StrokeMode::exact);
  CHECK_THROWS_WITH(parse_stroke_mode("sketchy"),
                    "strokes must be 'drawn' or 'exact', got 'sketchy'");
  CHECK(choice_list(kPlacementNames) == "'far' or 'near_and_far'");
}

TEST_CASE("the view's azimuth alone turns a run read window by window", "[adaptive][pipeline]") {
  // The source knows no view: setting params.view.azimuth_deg is all it takes, and the run equals
  // the whole grid turned for that azimuth.
  const HeightGrid z = rolling(70, 90);
  const DemSource source = memory_source(z, 10.0);
  for (const double azimuth : {0.0, 180.0, 30.0}) {
    CAPTURE(azimuth);
    SilhouetteParams p;
    p.view.azimuth_deg = azimuth;
    const OrientedFrame frame = make_frame(source.grid, azimuth);
    const SilhouetteResult streamed = sketch_silhouettes(source, p);
    const SilhouetteResult whole =
        frame.resampled
            ? run_resampled_silhouettes(z, frame, GeoTransform{}, p)
            : run_silhouettes(orient(z, frame), frame, GeoTransform{}, ResolvedParams(p));
    CHECK(streamed.stats.valid == whole.stats.valid);
    CHECK(streamed.stats.candidate == whole.stats.candidate);
    CHECK(streamed.stats.thinned == whole.stats.thinned);
    CHECK(streamed.strokes.size() == whole.strokes.size());
  }
}
