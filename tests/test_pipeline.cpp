#include <algorithm>
#include <atomic>
#include <chrono>
#include <set>
#include <thread>

#include "catch_compat.h"
#include "core/base/release_storage.h"
#include "spec_oracle.h"
#include "test_support.h"

using namespace tsk;

TEST_CASE("a front-facing tilted plane has no silhouettes", "[pipeline][analytic]") {
  // Rising 30 % towards the east, seen from the west.
  const HeightGrid dem = make_plane(50, 60, 10, 0.3, 0.05);
  const SilhouetteResult r = test::run_on_dem(dem, SilhouetteParams{});
  CHECK(r.stats.valid == 3000);
  CHECK(r.stats.hidden == 0);
  CHECK(r.stats.occluding == 0);
  CHECK(r.stats.candidate == 0);
  CHECK(r.strokes.empty());
}

TEST_CASE("a steep cone occludes where its transformed profile peaks", "[pipeline][analytic]") {
  // Cone of slope s = 0.5 seen from the west with ve 2.5, B 40 %: on the profile at distance y
  // from the apex, t peaks where ve s x / r = B, i.e. x* = |y| k / sqrt(1 - k^2), k = B/(ve s).
  const double cell = 10, s = 0.5;
  const std::size_t n = 81;
  const HeightGrid dem = make_cone(n, n, cell, 300, s);
  const SilhouetteResult r = test::run_on_dem(dem, SilhouetteParams{}, cell, cell);
  const double k = 0.4 / (2.5 * s);
  const double centre = (n - 1) / 2.0;
  int checked = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double y = std::fabs(static_cast<double>(p) - centre);
    if (y > 20) continue;  // stay well inside the cone's foot
    std::vector<std::size_t> occluders;
    for (std::size_t i = 0; i < n; ++i)
      if (r.flags(p, i) & cell::occluding) occluders.push_back(i);
    CAPTURE(p);
    REQUIRE(occluders.size() == 1);
    const double expected = centre + y * k / std::sqrt(1 - k * k);
    CHECK(std::fabs(static_cast<double>(occluders[0]) - expected) <= 1.0);
    ++checked;
  }
  CHECK(checked == 41);
  // The occluders chain into one factual stroke over the cone, symmetric north-south.
  REQUIRE(r.stats.factual_strokes >= 1);
  CHECK(r.strokes[0].cells >= 41);
}

TEST_CASE("a Gaussian bump: occlusion on its far side, symmetric north-south",
          "[pipeline][analytic]") {
  const std::size_t n = 61;
  const HeightGrid dem = make_bump(n, n, 200, 8);
  const SilhouetteResult r = test::run_on_dem(dem, SilhouetteParams{}, 10, 10);
  REQUIRE(r.stats.occluding > 0);
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t i = 0; i < n; ++i) {
      if (!(r.flags(p, i) & cell::occluding)) continue;
      CAPTURE(p, i);
      CHECK(i >= 30);  // never on the slope facing the viewer
      CHECK((r.flags(n - 1 - p, i) & cell::occluding));
    }
  // The c-set ring around the occluded back lies behind the centre too.
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t i = 0; i < 30; ++i) REQUIRE_FALSE(r.flags(p, i) & cell::candidate);
}

TEST_CASE("turning the DEM and the view by 90 degrees gives the same strokes",
          "[pipeline][invariance]") {
  const HeightGrid dem = test::random_terrain(70, 90, 99, 0.01);
  const HeightGrid turned = test::rotate_clockwise(dem);  // east becomes south
  for (double az : {0.0, 90.0, 180.0, 270.0}) {
    CAPTURE(az);
    SilhouetteParams a, b;
    a.view.azimuth_deg = az;
    b.view.azimuth_deg = std::fmod(az + 90, 360);
    const SilhouetteResult ra = test::run_on_dem(dem, a, 10, 10);
    const SilhouetteResult rb = test::run_on_dem(turned, b, 10, 10);
    REQUIRE(ra.strokes.size() == rb.strokes.size());
    REQUIRE(ra.strokes.size() > 10);
    CHECK(ra.stats.generalised == rb.stats.generalised);
    CHECK(ra.stats.filtered == rb.stats.filtered);
    for (std::size_t k = 0; k < ra.strokes.size(); ++k) {
      const Stroke& sa = ra.strokes[k];
      const Stroke& sb = rb.strokes[k];
      REQUIRE(sa.cls == sb.cls);
      REQUIRE(sa.points.size() == sb.points.size());
      if (sa.cls == StrokeClass::factual) CHECK(sa.mean_depth_m == Approx(sb.mean_depth_m));
      for (std::size_t q = 0; q < sa.points.size(); ++q) {
        // In pixel coordinates the turn maps (x, y) to (rows - y, x).
        REQUIRE(sb.points[q].x == Approx(70 - sa.points[q].y));
        REQUIRE(sb.points[q].y == Approx(sa.points[q].x));
      }
    }
  }
}

TEST_CASE("mirroring the DEM across the line of sight mirrors every stage",
          "[pipeline][invariance]") {
  const HeightGrid dem = test::random_terrain(50, 70, 123, 0.02);
  HeightGrid mirrored(dem.rows(), dem.cols());
  for (std::size_t r = 0; r < dem.rows(); ++r)
    std::copy(dem.row(r), dem.row(r) + dem.cols(), mirrored.row(dem.rows() - 1 - r));
  const SilhouetteResult a = test::run_on_dem(dem, SilhouetteParams{});
  const SilhouetteResult b = test::run_on_dem(mirrored, SilhouetteParams{});
  // Viewed from the west, profile p is row p: left and right swap.
  for (std::size_t p = 0; p < dem.rows(); ++p)
    REQUIRE(
        std::equal(a.flags.row(p), a.flags.row(p) + dem.cols(), b.flags.row(dem.rows() - 1 - p)));
  CHECK(a.stats.thinned == b.stats.thinned);
  CHECK(a.stats.occluding == b.stats.occluding);
}

TEST_CASE("stage statistics are consistent shares of the valid cells", "[pipeline]") {
  const SilhouetteResult r = test::run_on_dem(test::random_terrain(100, 100, 5, 0.1), {});
  const StageStats& s = r.stats;
  CHECK(s.valid < 10000);
  CHECK(s.valid > 8500);
  CHECK(s.filtered <= s.candidate);
  CHECK(s.thinned <= s.filtered);
  std::size_t cells = 0;
  for (const Stroke& st : r.strokes) cells += static_cast<std::size_t>(st.cells);
  CHECK(s.generalised == cells);
  CHECK(s.factual_strokes + s.formulated_strokes == r.strokes.size());
  CHECK(s.pct(s.valid) == Approx(100.0));
}

TEST_CASE("the minimum stroke length generalises", "[pipeline]") {
  const HeightGrid dem = test::random_terrain(80, 80, 17);
  SilhouetteParams two, five;
  two.chain.min_cells = 2;
  five.chain.min_cells = 5;
  const SilhouetteResult a = test::run_on_dem(dem, two);
  const SilhouetteResult b = test::run_on_dem(dem, five);
  std::size_t long_ones = 0;
  for (const Stroke& s : a.strokes) long_ones += s.cells >= 5;
  CHECK(b.strokes.size() == long_ones);
  CHECK(b.strokes.size() < a.strokes.size());
}

TEST_CASE("nodata, tiny grids and non-finite heights never break the pipeline",
          "[pipeline][robustness]") {
  SECTION("all nodata") {
    const HeightGrid dem(20, 30, kNoData);
    const SilhouetteResult r = test::run_on_dem(dem, {});
    CHECK(r.stats.valid == 0);
    CHECK(r.stats.pct(0) == 0.0);
    CHECK(r.strokes.empty());
  }
  SECTION("one row, one column, one cell") {
    for (auto [rows, cols] : {std::pair<std::size_t, std::size_t>{1, 50}, {50, 1}, {1, 1}}) {
      for (double az : {0.0, 90.0, 180.0, 270.0}) {
        SilhouetteParams p;
        p.view.azimuth_deg = az;
        const HeightGrid dem = test::random_terrain(rows, cols, 8);
        const SilhouetteResult r = test::run_on_dem(dem, p);
        CHECK(r.stats.valid == rows * cols);
        // One profile cannot chain; many one-cell profiles cannot either.
        CHECK(r.strokes.empty());
      }
    }
  }
  SECTION("NaN, infinities and huge values") {
    HeightGrid dem = test::random_terrain(30, 30, 4);
    dem(3, 3) = std::numeric_limits<float>::infinity();
    dem(4, 4) = -std::numeric_limits<float>::infinity();
    dem(5, 5) = kNoData;
    dem(6, 6) = 3.0e38f;
    dem(7, 7) = -3.0e38f;
    const SilhouetteResult r = test::run_on_dem(dem, {});
    CHECK(r.stats.valid == 900 - 3);
    for (const Stroke& s : r.strokes)
      for (const StrokePoint& pt : s.points) REQUIRE((std::isfinite(pt.x) && std::isfinite(pt.y)));
  }
  SECTION("holes") {
    const SilhouetteResult r = test::run_on_dem(test::random_terrain(60, 60, 6, 0.3), {});
    CHECK(r.stats.valid > 0);
    for (const Stroke& s : r.strokes)
      for (const ChainCell& c : s.chain) REQUIRE((r.flags(c.p, c.i) & cell::valid));
  }
}

TEST_CASE("non-square cells: the row slope uses the spacing across profiles", "[pipeline]") {
  // Heights from ground coordinates: a north-facing 15 % row slope is 15 % whatever the cells.
  const double dx = 10, dy = 25;
  HeightGrid dem(40, 40);
  for (std::size_t r = 0; r < 40; ++r)
    for (std::size_t c = 0; c < 40; ++c)
      dem(r, c) = static_cast<float>(0.15 * dy * r - 0.05 * dx * c);
  const OrientedFrame f = make_frame(40, 40, dx, dy, 90);
  const HeightGrid z = orient(dem, f);
  CHECK(std::fabs(row_slope(z, 10, 10, f.w)) == Approx(0.15));
  CHECK(column_slope(z.row(10), 40, 10, f.d) == Approx(-0.05));
}

TEST_CASE("threads do not change the result", "[pipeline]") {
  const HeightGrid dem = test::random_terrain(200, 150, 31, 0.02);
  SilhouetteParams one, two;
  one.threads = 1;
  two.threads = 2;
  const SilhouetteResult a = test::run_on_dem(dem, one);
  const SilhouetteResult b = test::run_on_dem(dem, two);
  REQUIRE(a.strokes.size() == b.strokes.size());
  CHECK(std::equal(a.flags.data(), a.flags.data() + a.flags.size(), b.flags.data()));
  for (std::size_t k = 0; k < a.strokes.size(); ++k)
    CHECK(a.strokes[k].cells == b.strokes[k].cells);
}

TEST_CASE("progress rises to one and cancelling stops the run", "[pipeline]") {
  // Progress is told batch by batch: 256 profiles of this length, so three batches.
  const HeightGrid dem = test::random_terrain(600, 8192, 2);
  const OrientedFrame f = make_frame(600, 8192, 10, 10, 90);
  const HeightGrid z = orient(dem, f);
  double last = 0;
  bool monotonic = true;
  run_silhouettes(z, f, GeoTransform{}, {}, [&](double fraction) {
    monotonic = monotonic && fraction >= last - 1e-12;
    last = fraction;
    return true;
  });
  CHECK(monotonic);
  CHECK(last == Approx(1.0));
  int calls = 0;
  CHECK_THROWS_AS(run_silhouettes(z, f, GeoTransform{}, {}, [&](double) { return ++calls < 3; }),
                  Cancelled);
  CHECK(calls == 3);
}

TEST_CASE("a grid that does not match its frame is refused", "[pipeline]") {
  const OrientedFrame f = make_frame(10, 20, 10, 10, 90);
  CHECK_THROWS_AS(run_silhouettes(HeightGrid(20, 10), f, GeoTransform{}, {}), Error);
}

namespace {

// Rows [first - 1, first + count + 1) of `z`, clipped to the grid: a strip with its neighbours.
HeightGrid strip_of(const HeightGrid& z, std::size_t first, std::size_t count) {
  const std::size_t lo = first > 0 ? first - 1 : 0;
  const std::size_t hi = std::min(z.rows(), first + count + 1);
  HeightGrid s(hi - lo, z.cols());
  for (std::size_t r = lo; r < hi; ++r) std::copy(z.row(r), z.row(r) + z.cols(), s.row(r - lo));
  return s;
}

}  // namespace

TEST_CASE("strips of any width give exactly the result of the whole grid", "[pipeline][strips]") {
  const HeightGrid dem = test::random_terrain(90, 70, 77, 0.03);
  for (double az : {90.0, 180.0, 30.0}) {
    SilhouetteParams params;
    params.view.azimuth_deg = az;
    params.geometry = Geometry::oblique;
    params.subcell = true;
    const OrientedFrame frame = make_frame(90, 70, 10, 10, az);
    const HeightGrid z = orient(dem, frame);
    const SilhouetteResult whole =
        run_silhouettes(z, frame, GeoTransform{}, ResolvedParams(params));
    for (std::size_t width : {1u, 7u, 64u}) {
      CAPTURE(az, width);
      SilhouetteStream stream(frame, GeoTransform{}, ResolvedParams(params), lowest_height(z));
      for (std::size_t first = 0; first < frame.profiles; first += width) {
        const std::size_t count = std::min(width, frame.profiles - first);
        stream.add_strip(strip_of(z, first, count), first, count);
      }
      const SilhouetteResult strips = stream.finish();
      CHECK(strips.stats.valid == whole.stats.valid);
      CHECK(strips.stats.filtered == whole.stats.filtered);
      CHECK(strips.stats.thinned == whole.stats.thinned);
      CHECK(strips.stats.generalised == whole.stats.generalised);
      test::require_same_strokes(whole, strips);
    }
  }
}

TEST_CASE("run_in_strips reads every strip with its neighbours and equals the whole grid",
          "[pipeline][strips]") {
  const HeightGrid dem = test::random_terrain(50, 40, 8, 0.02);
  const OrientedFrame frame = make_frame(50, 40, 10, 10, 270);
  const HeightGrid z = orient(dem, frame);
  const SilhouetteResult whole = run_silhouettes(z, frame, GeoTransform{}, {});
  std::vector<std::pair<std::size_t, std::size_t>> reads;
  const SilhouetteResult strips =
      run_in_strips(frame, GeoTransform{}, {}, lowest_height(z), 16,
                    [&](std::size_t first, std::size_t count, HeightGrid& s) {
                      reads.emplace_back(first, count);
                      s = HeightGrid(count, z.cols());
                      for (std::size_t r = 0; r < count; ++r)
                        std::copy(z.row(first + r), z.row(first + r) + z.cols(), s.row(r));
                    });
  // Strips of 2, 4, 8, then 16 profiles: 0-1 with 2; 2-5 with 1 and 6; 6-13 with 5 and 14; 14-29
  // with 13 and 30; 30-45 with 29 and 46; 46-49 with 45.
  CHECK(reads == std::vector<std::pair<std::size_t, std::size_t>>{
                     {0, 3}, {1, 6}, {5, 10}, {13, 18}, {29, 18}, {45, 5}});
  REQUIRE(strips.strokes.size() == whole.strokes.size());
  CHECK(strips.stats.generalised == whole.stats.generalised);
  CHECK_THROWS_AS(run_in_strips(frame, GeoTransform{}, {}, 0, 0, {}), Error);
}

TEST_CASE("strips are needed only for DEMs too large to hold and are sized by profile length",
          "[pipeline][strips]") {
  // Turned whole: 5 bytes a cell of the turned grid, with the DEM beside it when resampled.
  CHECK_FALSE(too_large_to_turn_whole(make_frame(100, 100, 10, 10, 90)));
  CHECK(
      too_large_to_turn_whole(make_frame(std::size_t{1} << 30, std::size_t{1} << 20, 10, 10, 90)));
  CHECK_FALSE(too_large_to_turn_whole(make_frame(1000, 1000, 10, 10, 45)));
  CHECK(too_large_to_turn_whole(make_frame(100000, 100000, 10, 10, 90)));
  CHECK(too_large_to_turn_whole(make_frame(100000, 100000, 10, 10, 45)));
  // Long profiles, fewer to a strip: 4 Mi cells, at least 256 profiles.
  CHECK(strip_profiles(make_frame(4096, 4096, 25, 25, 90)) == 1024);
  CHECK(strip_profiles(make_frame(8000, 8000, 25, 25, 90)) == 524);
  CHECK(strip_profiles(make_frame(8000, 8000, 25, 25, 0)) == 524);
  CHECK(strip_profiles(make_frame(20000, 20000, 25, 25, 90)) == 256);
  // Resampled too, as a band's edge blocks are kept for the next (io::BlockRetention).
  CHECK(strip_profiles(make_frame(8000, 8000, 25, 25, 45)) == 370);
  CHECK(strip_profiles(make_frame(40000, 40000, 25, 25, 45)) == 256);
  // Profiles so long that 256 of them would pass 512 MiB: fewer, at least 16.
  CHECK(strip_profiles(make_frame(300000, 300000, 25, 25, 90)) == 198);
  CHECK(strip_profiles(make_frame(1, 2000000000, 25, 25, 90)) == 16);
  // Short profiles, more to a strip: 1 Mi cells, at most 65536 profiles.
  CHECK(strip_profiles(make_frame(100000, 256, 25, 25, 90)) == 4096);
  CHECK(strip_profiles(make_frame(1000000, 1, 25, 25, 90)) == 65536);
  CHECK(is_cardinal(90));
  CHECK(is_cardinal(-180));
  CHECK_FALSE(is_cardinal(45));
}

TEST_CASE("an allocation over half of the machine's memory is refused before it is made",
          "[pipeline][memory]") {
  CHECK_NOTHROW(check_fits_in_memory(1e6, "a megabyte", "none"));
  // No machine this runs on has 2 exabytes: half of it is refused, naming what and the remedy.
  CHECK_THROWS_WITH(check_fits_in_memory(1e18, "the visibility of 4e+18 samples", "sample less"),
                    Catch::Contains("the visibility of 4e+18 samples would take 1000000000.0 GB, "
                                    "more than half of this machine's memory; sample less"));
}

TEST_CASE("storage released is let go, where assigning an empty list kept it",
          "[pipeline][memory]") {
  std::vector<StrokeVertex> vertices(1000);
  vertices = {};  // an empty initializer list assigned: emptied, its memory kept
  REQUIRE(vertices.capacity() >= 1000);
  release_storage(vertices);
  CHECK(vertices.capacity() == 0);
  std::vector<float, LargePageAllocator<float>> heights(1 << 20, 1.0f);  // a strip's buffer
  release_storage(heights);
  CHECK(heights.capacity() == 0);
}

TEST_CASE("strips must arrive in order and cover the grid", "[pipeline][strips]") {
  const HeightGrid z = test::random_terrain(10, 12, 3);
  const OrientedFrame frame = make_frame(10, 12, 10, 10, 90);
  SilhouetteStream stream(frame, GeoTransform{}, {}, 0.0);
  CHECK_THROWS_AS(stream.add_strip(strip_of(z, 2, 3), 2, 3), Error);  // a gap
  stream.add_strip(strip_of(z, 0, 4), 0, 4);
  CHECK_THROWS_AS(stream.finish(), Error);  // profiles 4..9 missing
}

TEST_CASE("a stroke sink gets every stroke as its chain completes, each class in scan order",
          "[pipeline][strips]") {
  const HeightGrid dem = test::random_terrain(300, 280, 21, 0.01);
  for (double az : {90.0, 30.0}) {
    // The strip being added as each stroke reached the sink, on the linking thread.
    std::vector<std::size_t> strip_of_stroke;
    // With threads, strokes are handed to the sink from a thread of their own, a batch at a time.
    for (const unsigned threads : {1u, 2u}) {
      CAPTURE(az, threads);
      SilhouetteParams params;
      params.view.azimuth_deg = az;
      params.subcell = true;
      params.threads = threads;
      const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), 10, 10, az);
      const HeightGrid z = orient(dem, frame);
      const SilhouetteResult held =
          run_silhouettes(z, frame, GeoTransform{}, ResolvedParams(params));
      REQUIRE(held.strokes.size() > 50);
      std::vector<Stroke> received;  // read once the run has finished
      std::atomic<std::size_t> received_count{0}, strip{0};
      SilhouetteStream stream(frame, GeoTransform{}, ResolvedParams(params), lowest_height(z), {},
                              [&](Stroke&& s) {
                                received.push_back(std::move(s));
                                ++received_count;
                                if (threads == 1) strip_of_stroke.push_back(strip.load());
                              });
      const std::size_t width = 20;
      for (std::size_t first = 0; first < frame.profiles; first += width, ++strip) {
        const std::size_t count = std::min(width, frame.profiles - first);
        stream.add_strip(strip_of(z, first, count), first, count);
      }
      const std::size_t received_before_finish = received_count.load();
      const SilhouetteResult streamed = stream.finish();
      CHECK(streamed.strokes.empty());
      CHECK(streamed.stats.factual_strokes == held.stats.factual_strokes);
      CHECK(streamed.stats.formulated_strokes == held.stats.formulated_strokes);
      CHECK(streamed.stats.generalised == held.stats.generalised);
      // Strokes leave as they complete, not at the end: only chains still open at the last
      // profile (and the strokes started after them) wait for finish().
      if (threads == 1) CHECK(received_before_finish > received.size() / 3);
      // With threads, the sink's thread may lag, but at most two batches (strips here): every
      // stroke completed three strips before the last has reached it, however the threads ran.
      if (threads == 2) {
        const std::size_t due = static_cast<std::size_t>(
            std::count_if(strip_of_stroke.begin(), strip_of_stroke.end(),
                          [&](std::size_t s) { return s + 3 < strip.load(); }));
        REQUIRE(due > 0);  // 161 of 222 strokes at 90°, 6 of 78 at 30° (a long chain open)
        CHECK(received_before_finish >= due);
      }
      // Each class arrives in the order of the held result; the classes are interleaved.
      SilhouetteResult regrouped;
      for (StrokeClass cls : {StrokeClass::factual, StrokeClass::formulated})
        for (const Stroke& s : received)
          if (s.cls == cls) regrouped.strokes.push_back(s);
      test::require_same_strokes(held, regrouped);
    }
  }
}

TEST_CASE("what a stroke sink throws ends the run", "[pipeline][strips]") {
  const HeightGrid dem = test::random_terrain(60, 60, 4);
  const OrientedFrame frame = make_frame(60, 60, 10, 10, 90);
  const HeightGrid z = orient(dem, frame);
  // Strokes are handed on from a thread of their own when there are threads.
  for (const StrokeMode mode : {StrokeMode::exact, StrokeMode::drawn}) {
    for (const unsigned threads : {1u, 2u}) {
      CAPTURE(mode == StrokeMode::drawn, threads);
      SilhouetteParams params;
      params.strokes.mode = mode;
      params.threads = threads;
      SilhouetteStream stream(frame, GeoTransform{}, ResolvedParams(params), 0.0, {},
                              [](Stroke&&) { throw Error("disk full"); });
      CHECK_THROWS_WITH(
          [&] {
            stream.add_strip(z, 0, frame.profiles);
            stream.finish();
          }(),
          "disk full");
    }
  }
}

TEST_CASE("tasks behind run in turn, fall at most so far behind, and pass on a failure",
          "[pipeline]") {
  std::atomic<int> done{0};
  std::vector<int> order;
  {
    TasksBehind tasks(2, true);
    for (int k = 0; k < 20; ++k) {
      tasks.run([&, k] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        order.push_back(k);
        ++done;
      });
      // The task just given and at most two before it may be unfinished.
      CHECK(done.load() >= k - 2);
    }
    tasks.finish();
  }
  REQUIRE(order.size() == 20);
  for (int k = 0; k < 20; ++k) CHECK(order[static_cast<std::size_t>(k)] == k);
  // A failure comes out of a later run() or of finish().
  TasksBehind failing(1, true);
  CHECK_THROWS_WITH(
      [&] {
        failing.run([] { throw Error("write failed"); });
        for (int k = 0; k < 3; ++k) failing.run([] {});
        failing.finish();
      }(),
      "write failed");
  // Without a thread of its own, a task runs at once and throws there.
  TasksBehind in_turn(2, false);
  bool ran = false;
  in_turn.run([&ran] { ran = true; });
  CHECK(ran);
  CHECK_THROWS_WITH(in_turn.run([] { throw Error("at once"); }), "at once");
}

TEST_CASE("two shares run at once, and a failure of either stops the other and is passed on",
          "[pipeline]") {
  // Both on threads of their own at once: each waits until the other has begun.
  std::atomic<int> begun{0};
  std::thread::id threads[2];
  run_two_shares(true, [&](int share, const std::atomic<bool>&) {
    threads[share] = std::this_thread::get_id();
    ++begun;
    while (begun.load() < 2) std::this_thread::yield();
  });
  CHECK(threads[0] == std::this_thread::get_id());
  CHECK(threads[1] != threads[0]);
  // One share only when not two.
  std::vector<int> ran;
  run_two_shares(false, [&](int share, const std::atomic<bool>&) { ran.push_back(share); });
  CHECK(ran == std::vector<int>{0});
  // The second share fails after the first has begun; the first sees `stop` and ends early.
  for (const int failing : {0, 1}) {
    CAPTURE(failing);
    std::atomic<bool> started{false}, stopped_early{false};
    CHECK_THROWS_WITH(run_two_shares(true,
                                     [&](int share, const std::atomic<bool>& stop) {
                                       if (share == failing) {
                                         while (!started) std::this_thread::yield();
                                         throw Error("read failed");
                                       }
                                       started = true;
                                       while (!stop) std::this_thread::yield();
                                       stopped_early = true;
                                     }),
                      "read failed");
    CHECK(stopped_early);
  }
  // Both fail: the caller's own failure is the one passed on.
  CHECK_THROWS_WITH(run_two_shares(true,
                                   [&](int share, const std::atomic<bool>&) {
                                     throw Error(share == 0 ? "mine" : "theirs");
                                   }),
                    "mine");
}

TEST_CASE("a hand-off takes every item in order, a batch at a time, and passes on a failure",
          "[pipeline]") {
  for (const bool alongside : {true, false}) {
    CAPTURE(alongside);
    std::vector<int> taken;
    std::thread::id taker;
    HandOff<int> hand_off(
        [&](int&& item) {
          taken.push_back(item);
          taker = std::this_thread::get_id();
        },
        alongside);
    for (int batch = 0; batch < 5; ++batch) {
      for (int k = 0; k < 7; ++k) hand_off.add(batch * 7 + k);
      hand_off.flush();
    }
    hand_off.add(35);
    hand_off.finish();  // hands on the last item, not flushed yet
    REQUIRE(taken.size() == 36);
    for (int k = 0; k < 36; ++k) CHECK(taken[static_cast<std::size_t>(k)] == k);
    CHECK((taker != std::this_thread::get_id()) == alongside);
  }
  HandOff<int> failing([](int&&) { throw Error("disk full"); }, true);
  CHECK_THROWS_WITH(
      [&] {
        for (int batch = 0; batch < 4; ++batch) {
          failing.add(1);
          failing.flush();
        }
        failing.finish();
      }(),
      "disk full");
}

TEST_CASE("batch storage gives back the storage of batches done with, emptied", "[pipeline]") {
  BatchStorage<std::vector<std::vector<int>>> storage;
  CHECK(storage.take().capacity() == 0);  // none given back yet
  std::vector<std::vector<int>> done(100, std::vector<int>(3, 7));
  const auto* memory = done.data();
  storage.give_back(std::move(done));
  std::vector<std::vector<int>> again = storage.take();
  CHECK(again.empty());  // its items gone
  CHECK(again.capacity() >= 100);
  CHECK(again.data() == memory);          // the same storage, not a copy
  CHECK(storage.take().capacity() == 0);  // taken once only
  // It keeps a few, not every batch ever given back.
  for (int k = 0; k < 10; ++k) storage.give_back(std::vector<std::vector<int>>(50));
  int kept = 0;
  while (storage.take().capacity() > 0) ++kept;
  CHECK(kept >= 1);
  CHECK(kept <= 4);
}

TEST_CASE("strips too wide for the machine's memory are refused before any read",
          "[pipeline][strips]") {
  // Profiles 2^24 cells long: 2^16 of them in a strip would be 9 TiB.
  const OrientedFrame frame = make_frame(std::size_t{1} << 16, std::size_t{1} << 24, 10, 10, 90);
  bool read = false;
  const ProfileReader reader = [&read](std::size_t, std::size_t, HeightGrid&) { read = true; };
  CHECK_THROWS_WITH(run_in_strips(frame, {}, {}, 0.0, std::size_t{1} << 16, reader),
                    Catch::Contains("more than half of this machine's memory"));
  CHECK_FALSE(read);
  CHECK(strip_profiles(frame) == 16);
}

TEST_CASE("stage counts are the flags counted, on profiles longer than a counting block",
          "[pipeline]") {
  // Counts are gathered eight cells at a time in blocks of 2040 cells: lengths around that.
  for (std::size_t cols : {7u, 2040u, 2047u, 4099u}) {
    INFO(cols << " cells a profile");
    HeightGrid dem = test::random_terrain(5, cols, static_cast<std::uint32_t>(cols), 0.05);
    dem(2, cols / 2) = std::numeric_limits<float>::infinity();
    const SilhouetteResult r = test::run_on_dem(dem, {});
    StageStats counted;
    for (std::size_t p = 0; p < r.flags.rows(); ++p)
      for (std::size_t i = 0; i < r.flags.cols(); ++i) {
        const std::uint8_t f = r.flags(p, i);
        counted.valid += (f & cell::valid) != 0, counted.hidden += (f & cell::hidden) != 0;
        counted.occluding += (f & cell::occluding) != 0;
        counted.candidate += (f & cell::candidate) != 0;
        counted.filtered += (f & cell::filtered) != 0, counted.thinned += (f & cell::thinned) != 0;
      }
    CHECK(r.stats.valid == counted.valid);
    CHECK(r.stats.hidden == counted.hidden);
    CHECK(r.stats.occluding == counted.occluding);
    CHECK(r.stats.candidate == counted.candidate);
    CHECK(r.stats.filtered == counted.filtered);
    CHECK(r.stats.thinned == counted.thinned);
    if (cols > 100) CHECK(counted.thinned > 0);  // the counts were put to the test
  }
}

TEST_CASE("the pipeline classifies every cell as SPEC 1.2-1.6 say, nodata included",
          "[pipeline][oracle]") {
  // The oracle (spec_oracle.h) is written from the SPEC's words alone. Random terrain with margins
  // of 0 to 25 nodata cells (NaN or infinite) before and after each profile's data, which the
  // pipeline skips, and holes inside; both filter shapes and both placements; integer heights
  // (seed 24), whose plateaus and equal heights test the strict comparisons.
  const std::uint32_t seed = GENERATE(21u, 22u, 23u, 24u);
  CAPTURE(seed);
  std::mt19937 rng(seed);
  HeightGrid dem = test::random_terrain(80, 120, seed, 0.02);
  if (seed == 24u)
    for (std::size_t k = 0; k < dem.size(); ++k) dem.data()[k] = std::round(dem.data()[k]);
  const float nodata[] = {kNoData, std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  for (std::size_t p = 0; p < dem.rows(); ++p) {
    const std::size_t before = rng() % 26, after = rng() % 26;
    for (std::size_t i = 0; i < before; ++i) dem(p, i) = nodata[rng() % 3];
    for (std::size_t i = 0; i < after; ++i) dem(p, dem.cols() - 1 - i) = nodata[rng() % 3];
  }
  for (int hole = 0; hole < 40; ++hole) dem(rng() % dem.rows(), rng() % dem.cols()) = kNoData;
  SilhouetteParams params;
  params.filter.diagonals = seed != 22u;
  params.placement = seed == 23u ? Placement::near_and_far : Placement::far;
  const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), 10, 12, 90);  // from the west
  const SilhouetteResult r = run_silhouettes(dem, frame, GeoTransform{}, ResolvedParams(params));
  const CellFlags expected = oracle::classify(dem, frame.d, frame.w, params);
  std::size_t counts[6] = {};
  for (std::size_t p = 0; p < dem.rows(); ++p)
    for (std::size_t i = 0; i < dem.cols(); ++i) {
      INFO("profile " << p << ", cell " << i);
      REQUIRE(static_cast<int>(r.flags(p, i)) == static_cast<int>(expected(p, i)));
      for (int bit = 0; bit < 6; ++bit) counts[bit] += (expected(p, i) >> bit) & 1;
    }
  // Every stage has cells to compare.
  for (int bit = 1; bit < 6; ++bit) CHECK(counts[bit] > 10);
  CHECK(r.stats.filtered == counts[4]);
  CHECK(r.stats.thinned == counts[5]);
}

TEST_CASE("a worker runs its tasks in turn on one thread of its own", "[pipeline]") {
  std::vector<std::thread::id> ran;
  {
    Worker worker;
    std::vector<std::future<void>> done;
    for (int k = 0; k < 5; ++k)
      done.push_back(worker.run([&ran] { ran.push_back(std::this_thread::get_id()); }));
    done.push_back(worker.run([] { throw Error("read failed"); }));
    for (int k = 0; k < 5; ++k) done[static_cast<std::size_t>(k)].get();
    CHECK_THROWS_WITH(done.back().get(), "read failed");
    worker.run([&ran] { ran.push_back(std::this_thread::get_id()); });  // finished on destruction
  }
  REQUIRE(ran.size() == 6);
  CHECK(std::all_of(ran.begin(), ran.end(), [&](std::thread::id id) { return id == ran.front(); }));
  CHECK(ran.front() != std::this_thread::get_id());
  // Without a thread of its own, a task runs on the caller's thread when its result is asked for.
  Worker in_turn(false);
  bool run = false;
  std::future<void> later = in_turn.run([&run] { run = true; });
  CHECK_FALSE(run);
  later.get();
  CHECK(run);
}
