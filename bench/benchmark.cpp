// Benchmark: each stage and the whole pipeline on synthetic DEMs, cells per second and peak
// memory; with GDAL, the command line end to end against `gdaldem hillshade` on the same file.
// Each size runs in its own child process so its peak memory is its own.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/terrain_sketch.h"
#include "resampled_silhouettes.h"
#include "whole_grid_stages.h"

#ifdef TSK_BENCH_WITH_GDAL
#include <gdal_priv.h>

#include "io/read/dem_reader.h"
#endif

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// The memory the process holds now (resident set), in MiB.
double current_rss_mib() {
  long pages = 0, resident = 0;
  if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(statm);
  }
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
         (1024.0 * 1024.0);
}

// Rolling synthetic terrain: ridges and valleys at several scales, 25 m cells.
tsk::HeightGrid synthetic_dem(std::size_t rows, std::size_t cols) {
  tsk::HeightGrid g(rows, cols);
  tsk::parallel_for(rows, 0, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      float* row = g.row(r);
      const double y = static_cast<double>(r);
      for (std::size_t c = 0; c < cols; ++c) {
        const double x = static_cast<double>(c);
        const double z = 400 + 180 * std::sin(x * 0.011 + 0.4 * std::sin(y * 0.007)) +
                         120 * std::sin(y * 0.013 + x * 0.004) +
                         40 * std::sin(x * 0.071 + y * 0.053) + 15 * std::sin(x * 0.23 - y * 0.19);
        row[c] = static_cast<float>(z);
      }
    }
  });
  return g;
}

// Terrain that looks the same from every side: round hills of many sizes at random places,
// 25 m cells. Its silhouettes cost the same at any azimuth, so comparing two azimuths on it
// measures what a non-cardinal view itself costs (the rolling terrain above has twice the
// occluding cells seen at 45 degrees as at 90).
tsk::HeightGrid round_hills_dem(std::size_t n) {
  struct Hill {
    double x, y, radius, height;
  };
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Hill> hills;
  // Radii log-uniform from 30 to 300 cells, heights 0.6 m per metre of radius: the hills cover
  // the DEM about three times over.
  double covered = 0;
  while (covered < 3.0 * static_cast<double>(n) * static_cast<double>(n)) {
    const double radius = 30 * std::pow(10.0, unit(random));
    hills.push_back({unit(random) * static_cast<double>(n), unit(random) * static_cast<double>(n),
                     radius, 0.6 * 25 * radius});
    covered += M_PI * radius * radius;
  }
  tsk::HeightGrid g(n, n, 100.0f);
  tsk::parallel_for(n, 0, [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      float* row = g.row(r);
      const double y = static_cast<double>(r);
      for (const Hill& h : hills) {
        const double dy = y - h.y;
        if (std::abs(dy) >= h.radius) continue;
        const double half = std::sqrt(h.radius * h.radius - dy * dy);
        const auto c0 = static_cast<std::size_t>(std::clamp(h.x - half, 0.0, double(n)));
        const auto c1 = static_cast<std::size_t>(std::clamp(h.x + half + 1, 0.0, double(n)));
        for (std::size_t c = c0; c < c1; ++c) {
          const double dist = std::hypot(static_cast<double>(c) - h.x, dy);
          if (dist < h.radius) {
            row[c] += static_cast<float>(h.height * 0.5 * (1 + std::cos(M_PI * dist / h.radius)));
          }
        }
      }
    }
  });
  return g;
}

#ifdef TSK_BENCH_WITH_GDAL
void write_geotiff(const std::string& path, const tsk::HeightGrid& dem) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  const char* options[] = {"TILED=YES", nullptr};
  const int n = static_cast<int>(dem.rows());
  GDALDataset* ds = drv->Create(path.c_str(), n, n, 1, GDT_Float32, const_cast<char**>(options));
  double gt[6] = {500000, 25, 0, 5000000, 0, -25};
  ds->SetGeoTransform(gt);
  OGRSpatialReference srs;
  srs.importFromEPSG(32632);
  ds->SetSpatialRef(&srs);
  if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, n, n, const_cast<float*>(dem.data()), n, n,
                                     GDT_Float32, 0, 0) != CE_None) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
  }
  GDALClose(ds);
}

// What `command` writes on stderr (its stdout dropped).
std::string command_stderr(const std::string& command) {
  std::string text;
  if (FILE* pipe = popen((command + " 2>&1 > /dev/null").c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    pclose(pipe);
  }
  return text;
}

// Processor time (user and system) of the finished child processes so far.
double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Wall and processor time of a command run as a new process.
struct CommandTime {
  double wall, cpu;
};

CommandTime time_command(const std::string& command) {
  const double cpu = children_cpu_seconds();
  const auto t = Clock::now();
  if (std::system(command.c_str()) != 0) std::fprintf(stderr, "failed: %s\n", command.c_str());
  return {seconds_since(t), children_cpu_seconds() - cpu};
}
#endif

void print_stages(const char* label, const tsk::StageTimings& t, double whole, double cells) {
  std::printf(
      "  %-22s visibility %.3f | candidates %.3f | filter %.3f | thinning %.3f | "
      "chaining %.3f | strokes %.3f | whole %.3f s, %.1f Mcells/s\n",
      label, t.visibility, t.candidates, t.filter, t.thinning, t.chaining, t.strokes, whole,
      cells / whole / 1e6);
}

// Runs the pipeline once; `orient_s` gets the time spent turning or resampling the DEM.
tsk::SilhouetteResult run_once(const tsk::HeightGrid& dem, double azimuth, unsigned threads,
                               double& orient_s) {
  tsk::SilhouetteParams params;
  params.view.azimuth_deg = azimuth;
  params.threads = threads;
  const tsk::OrientedFrame frame = tsk::make_frame(dem.rows(), dem.cols(), 25, 25, azimuth);
  // Viewed from the west the oriented grid is the DEM itself: no copy, as the reader does.
  // Other azimuths resample strip by strip as the stages go, as the command-line tool does.
  orient_s = 0;
  if (frame.resampled) {
    tsk::SilhouetteResult r = tsk::run_resampled_silhouettes(dem, frame, {}, params);
    orient_s = r.timings.resampling;
    return r;
  }
  if (frame.azimuth_deg == 90)
    return tsk::run_silhouettes(dem, frame, {}, tsk::ResolvedParams(params));
  const auto t_orient = Clock::now();
  const tsk::HeightGrid oriented = tsk::orient(dem, frame, threads);
  orient_s = seconds_since(t_orient);
  return tsk::run_silhouettes(oriented, frame, {}, tsk::ResolvedParams(params));
}

// Runs the pipeline three times (this shared machine varies by 10-30 % from run to run),
// prints the stages of the median run and returns its wall time. One result is alive at a time,
// so the peak memory is that of one run.
double timed_run(const tsk::HeightGrid& dem, double azimuth, unsigned threads, const char* label,
                 tsk::StageStats* stats = nullptr) {
  struct Run {
    double whole, orient_s;
    tsk::StageTimings timings;
  };
  std::vector<Run> runs(3);
  for (Run& run : runs) {
    const auto t = Clock::now();
    const tsk::SilhouetteResult result = run_once(dem, azimuth, threads, run.orient_s);
    run.whole = seconds_since(t);
    run.timings = result.timings;
    if (stats) *stats = result.stats;
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.whole < b.whole; });
  const Run& median = runs[1];
  print_stages(label, median.timings, median.whole, static_cast<double>(dem.size()));
  if (median.orient_s > 0) {
    std::printf("  %-22s (%s %.3f s; runs %.3f / %.3f / %.3f s)\n", "",
                tsk::is_cardinal(azimuth) ? "turning the DEM, before the stages,"
                                          : "resampling, alongside the stages,",
                median.orient_s, runs[0].whole, runs[1].whole, runs[2].whole);
  } else {
    std::printf("  %-22s (runs %.3f / %.3f / %.3f s)\n", "", runs[0].whole, runs[1].whole,
                runs[2].whole);
  }
  return median.whole;
}

// The stages that run profile by profile, from visibility to thinning, each over the whole grid
// on `threads` threads (seen from the west the DEM is the oriented grid): the median of three.
double per_profile_stages(const tsk::HeightGrid& dem, unsigned threads) {
  const tsk::SilhouetteParams params;
  const double d = 25, w = 25;
  std::vector<double> runs;
  tsk::CellFlags flags;
  for (int run = 0; run < 3; ++run) {
    const auto t = Clock::now();
    tsk::classify_visibility(dem, d, params.view, flags, threads);
    tsk::select_candidates(dem, d, params.view, flags, threads);
    tsk::apply_slope_filter(dem, d, w, params.filter, flags, threads);
    tsk::thin(flags, params.placement, threads);
    runs.push_back(seconds_since(t));
  }
  std::sort(runs.begin(), runs.end());
  return runs[1];
}

void bench_size(std::size_t n, bool with_gdaldem) {
  const double baseline = current_rss_mib();
  const auto t_gen = Clock::now();
  const tsk::HeightGrid dem = synthetic_dem(n, n);
  const double gen = seconds_since(t_gen);
  const double raster_mib = static_cast<double>(dem.size() * sizeof(float)) / (1024.0 * 1024.0);
  std::printf("\n== synthetic %zux%zu (%.0f MiB Float32), generated in %.2f s\n", n, n, raster_mib,
              gen);
  tsk::StageStats stats;
  const double whole = timed_run(dem, 90, 0, "azimuth 90, all cores", &stats);
  const double peak = peak_rss_mib();
  std::printf(
      "  %zu factual + %zu formulated strokes; c-set %.1f %%, f-set %.1f %%, t-set %.1f %%, "
      "g-set %.1f %%\n",
      stats.factual_strokes, stats.formulated_strokes, stats.pct(stats.candidate),
      stats.pct(stats.filtered), stats.pct(stats.thinned), stats.pct(stats.generalised));
  std::printf(
      "  peak memory %.0f MiB = %.2f x the raster's bytes (%.0f MiB of it held before the DEM "
      "was made: the program and its libraries)\n",
      peak, peak / raster_mib, baseline);
  const double single = timed_run(dem, 90, 1, "azimuth 90, 1 thread");
  std::printf("  %-22s %.2f x on %u threads\n", "thread speed-up", single / whole,
              tsk::resolve_threads(0));
  const double stages_1 = per_profile_stages(dem, 1), stages_all = per_profile_stages(dem, 0);
  std::printf(
      "  %-22s visibility to thinning, grid by grid: %.3f s on 1 thread, %.3f s on %u: "
      "%.2f x\n",
      "per-profile stages", stages_1, stages_all, tsk::resolve_threads(0), stages_1 / stages_all);
  tsk::StageStats oblique_stats;
  const double oblique = timed_run(dem, 45, 0, "azimuth 45, all cores", &oblique_stats);
  std::printf("  %-22s %.2f x the cardinal time (occluding cells %.2f %% at 45, %.2f %% at 90)\n",
              "non-cardinal cost", oblique / whole, oblique_stats.pct(oblique_stats.occluding),
              stats.pct(stats.occluding));
  {
    const tsk::HeightGrid hills = round_hills_dem(n);
    tsk::StageStats at_90, at_45;
    const double hills_90 = timed_run(hills, 90, 0, "round hills, azimuth 90", &at_90);
    const double hills_45 = timed_run(hills, 45, 0, "round hills, azimuth 45", &at_45);
    std::printf(
        "  %-22s on round hills, the same from every side: %.2f x the cardinal time "
        "(occluding cells %.2f %% at 45, %.2f %% at 90)\n",
        "non-cardinal cost", hills_45 / hills_90, at_45.pct(at_45.occluding),
        at_90.pct(at_90.occluding));
  }
#ifdef TSK_BENCH_WITH_GDAL
  if (with_gdaldem) {
    const std::string dir = "/tmp/tsk-bench-" + std::to_string(getpid());
    std::system(("mkdir -p " + dir).c_str());
    const std::string tif = dir + "/dem.tif";
    write_geotiff(tif, dem);
    // Both as new processes, in turn, three times each: medians, since this machine is noisy.
    std::vector<double> hillshade, cli, cli_45, hillshade_cpu, cli_cpu;
    const std::string silhouettes =
        std::string(TSK_BENCH_CLI) + " silhouettes " + tif + " " + dir + "/out.gpkg";
    for (int run = 0; run < 3; ++run) {
      const CommandTime shade = time_command("gdaldem hillshade -q " + tif + " " + dir + "/hs.tif");
      const CommandTime sketch = time_command(silhouettes + " > /dev/null");
      hillshade.push_back(shade.wall), hillshade_cpu.push_back(shade.cpu);
      cli.push_back(sketch.wall), cli_cpu.push_back(sketch.cpu);
      cli_45.push_back(time_command(silhouettes + " --azimuth 45 > /dev/null").wall);
    }
    const auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[1];
    };
    std::printf(
        "  gdaldem hillshade %.3f s | terrain-sketch CLI end to end (read, silhouettes, "
        "write GeoPackage) %.3f s | ratio CLI/hillshade %.2f | pipeline/hillshade %.2f\n",
        median(hillshade), median(cli), median(cli) / median(hillshade), whole / median(hillshade));
    std::printf("  %-22s (hillshade runs %.3f / %.3f / %.3f s; CLI runs %.3f / %.3f / %.3f s)\n",
                "", hillshade[0], hillshade[1], hillshade[2], cli[0], cli[1], cli[2]);
    std::printf("  CLI end to end at azimuth 45 %.3f s = %.2f x the cardinal run\n", median(cli_45),
                median(cli_45) / median(cli));
    // What the wall times can come to: the CLI's processor time spread over every core.
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    std::printf(
        "  processor time (user + system): CLI %.3f s, gdaldem hillshade %.3f s; spread over %u "
        "cores the CLI could take no less than %.3f s = %.2f x the hillshade\n",
        median(cli_cpu), median(hillshade_cpu), cores, median(cli_cpu) / cores,
        median(cli_cpu) / cores / median(hillshade));
    std::printf("  CLI %s", command_stderr(silhouettes + " --timings").c_str());
    std::system(("rm -rf " + dir).c_str());
  }
#else
  (void)with_gdaldem;
#endif
}

// A long strip of terrain seen along it and across it: a million profiles of 64 cells, then 64
// profiles of a million cells, where the cost of each profile and of each cell show.
void bench_elongated() {
  const std::size_t rows = 64, cols = 1000000;
  const tsk::HeightGrid dem = synthetic_dem(rows, cols);
  std::printf("\n== synthetic %zux%zu, seen along it and across it\n", rows, cols);
  const double along = timed_run(dem, 0, 0, "azimuth 0, all cores");
  std::printf("  %-22s %zu profiles of %zu cells: %.0f ns a profile\n", "", cols, rows,
              1e9 * along / static_cast<double>(cols));
  const double across = timed_run(dem, 90, 0, "azimuth 90, all cores");
  std::printf("  %-22s %zu profiles of %zu cells: %.2f x the time along it\n", "", rows, cols,
              across / along);
}

#ifdef TSK_BENCH_WITH_GDAL
void bench_real_dems() {
  std::printf("\n== real DEMs (tests/data), all cores, read through GDAL\n");
  for (const char* name : {"jacksboro_utm16n.tif", "gorillas_utm32n.tif", "volcano.tif",
                           "bei_5m_local.tif", "topobathy_3857.tif"}) {
    const std::string path = std::string(TSK_BENCH_DATA) + "/" + name;
    tsk::io::DemOptions options;
    const auto t_read = Clock::now();
    const tsk::io::Dem dem = tsk::io::read_dem(path, options, 90.0);
    const double read_s = seconds_since(t_read);
    const auto t = Clock::now();
    const tsk::SilhouetteResult r =
        tsk::run_silhouettes(dem.oriented, dem.frame, dem.geotransform, {});
    const double whole = seconds_since(t);
    std::printf(
        "  %-22s %zux%zu: read %.3f s, pipeline %.4f s (%.1f Mcells/s), %zu + %zu strokes\n", name,
        dem.rows, dem.cols, read_s, whole, static_cast<double>(dem.rows * dem.cols) / whole / 1e6,
        r.stats.factual_strokes, r.stats.formulated_strokes);
    const tsk::StageTimings& stage = r.timings;
    std::printf(
        "  %-22s stages (ms): visibility %.2f | candidates %.2f | filter %.2f | thinning %.2f | "
        "chaining %.2f | strokes %.2f\n",
        "", 1e3 * stage.visibility, 1e3 * stage.candidates, 1e3 * stage.filter,
        1e3 * stage.thinning, 1e3 * stage.chaining, 1e3 * stage.strokes);
  }
}
#endif

// Runs `bench` in a process of its own, so that its peak memory is its own; false if it failed.
template <typename Bench>
bool in_child(Bench&& bench) {
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    bench();
    std::fflush(stdout);
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes = {4000, 8000};
  bool with_gdaldem = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--gdaldem") {
      with_gdaldem = true;
#ifdef TSK_BENCH_WITH_GDAL
    } else if (a == "--write-dem" && k + 2 < argc) {
      // The synthetic DEM of the benchmark as a GeoTIFF, for comparing outputs across changes.
      const std::size_t n = std::stoul(argv[k + 2]);
      write_geotiff(argv[k + 1], synthetic_dem(n, n));
      return 0;
#endif
    } else if (a == "--sizes" && k + 1 < argc) {
      sizes.clear();
      std::string list = argv[++k];
      for (std::size_t pos = 0; pos < list.size();) {
        const std::size_t comma = list.find(',', pos);
        sizes.push_back(std::stoul(list.substr(pos, comma - pos)));
        pos = comma == std::string::npos ? list.size() : comma + 1;
      }
    } else {
      std::fprintf(
          stderr,
          "usage: tsk_benchmark [--sizes 4000,8000] [--gdaldem] | --write-dem FILE.tif N\n");
      return 2;
    }
  }
  std::printf("terrain-sketch benchmark, %u hardware threads\n", tsk::resolve_threads(0));
#ifdef TSK_BENCH_WITH_GDAL
  bench_real_dems();
#endif
  for (std::size_t n : sizes) {
    if (!in_child([&] { bench_size(n, with_gdaldem); })) std::printf("  size %zu failed\n", n);
  }
  if (!in_child(bench_elongated)) std::printf("  the elongated DEM failed\n");
  return 0;
}
