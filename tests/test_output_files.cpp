// Outputs put in place whole (io/output_files.h): the files of an earlier output all replaced,
// and concurrent runs of the command line for one output never leaving a mixed set.
#include <fcntl.h>
#include <gdal_utils.h>
#include <ogrsf_frmts.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/vfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "catch_compat.h"
#include "cli_run.h"
#include "gdal_test_support.h"
#include "io/read/gdal_util.h"
#include "io/write/destination_lock.h"
#include "io/write/early_writeback.h"
#include "io/write/output_files.h"
#include "io/write/path_clashes.h"
#include "io/write/raster_writer.h"

using namespace tsk;
using namespace tsk::test;

namespace {

const std::string kSample = TSK_SAMPLE_DEM;

// The features of a line layer read whole, or -1 when GDAL fails anywhere while reading it (a
// shapefile whose .shp, .shx and .dbf come from different runs).
long long features_read(const std::string& path, const OGREnvelope* filter = nullptr) {
  GDALAllRegister();
  const io::GdalErrorCapture errors;
  io::DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!ds || ds->GetLayerCount() != 1) return -1;
  OGRLayer* layer = ds->GetLayer(0);
  if (filter) layer->SetSpatialFilterRect(filter->MinX, filter->MinY, filter->MaxX, filter->MaxY);
  long long count = 0;
  for (auto& feature : *layer) count += feature->GetGeometryRef() != nullptr;
  const long long declared = layer->GetFeatureCount(TRUE);
  return errors.first_failure().empty() && (filter || declared == count) ? count : -1;
}

// Starts the command line on `args`, its output to /dev/null and its messages to `messages`.
pid_t start_cli(const std::vector<std::string>& args, const std::string& messages = "/dev/null") {
  std::vector<char*> argv = {const_cast<char*>("terrain-sketch")};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, 2, messages.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  const int started = posix_spawn(&child, TSK_CLI_BINARY, &quiet, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&quiet);
  REQUIRE(started == 0);
  return child;
}

int exit_code(pid_t child) {
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The staging folder run `pid` made in `dir`, or an empty path while there is none.
std::filesystem::path staging_of(const std::filesystem::path& dir, pid_t pid) {
  const std::string mark = ".partial-" + std::to_string(pid);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const std::size_t at = name.find(mark);
    if (at != std::string::npos &&
        (at + mark.size() == name.size() || name[at + mark.size()] == '-'))
      return entry.path();
  }
  return {};
}

// Waits until the file at `path` holds `text`; false after a minute.
bool said(const std::string& path, const std::string& text) {
  for (int k = 0; k < 3000; ++k) {
    if (slurp(path).find(text) != std::string::npos) return true;
    usleep(20000);
  }
  return false;
}

// Waits until run `pid` has begun to stage `file` in `dir`; false after a minute.
bool staged(const std::filesystem::path& dir, pid_t pid, const std::string& file) {
  for (int k = 0; k < 3000; ++k) {
    const std::filesystem::path staging = staging_of(dir, pid);
    if (!staging.empty() && std::filesystem::exists(staging / file)) return true;
    usleep(20000);
  }
  return false;
}

}  // namespace

TEST_CASE("concurrent runs into one shapefile leave one run's whole set", "[io][concurrency]") {
  ScratchDir dir("concurrent");
  const std::vector<std::string> azimuths = {"90", "0", "200"};
  // What each view alone writes.
  std::set<long long> whole_sets;
  for (const std::string& az : azimuths) {
    const std::string alone = dir / ("alone" + az + ".shp");
    REQUIRE(run_cli({"silhouettes", kSample, alone, "--azimuth", az}).code == 0);
    whole_sets.insert(features_read(alone));
  }
  REQUIRE(whole_sets.size() == 3);  // the views give different sets
  const std::string shared = dir / "c.shp";
  for (int round = 0; round < 20; ++round) {
    CAPTURE(round);
    std::vector<pid_t> runs;
    for (const std::string& az : azimuths)
      runs.push_back(start_cli({"silhouettes", kSample, shared, "--azimuth", az},
                               dir / ("messages" + az + ".txt")));
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const int code = exit_code(runs[k]);
      INFO("from " << azimuths[k] << ": " << slurp(dir / ("messages" + azimuths[k] + ".txt")));
      REQUIRE(code == 0);
    }
    REQUIRE(whole_sets.count(features_read(shared)) == 1);
  }
}

TEST_CASE("a run waits to put its output in place while another run holds it",
          "[io][concurrency]") {
  // The other run is this test, holding the destination's lock: the command line's run must
  // finish its work and wait, leaving the destination alone, until the lock is released.
  ScratchDir dir("held");
  const std::string out = dir / "held.shp", messages = dir / "messages.txt";
  pid_t run = 0;
  {
    const io::DestinationLock held(out);
    run = start_cli({"silhouettes", kSample, out}, messages);
    REQUIRE(staged(dir.path, run, "held.dbf"));  // its strokes go to its staging folder
    // Its work done, it waits for the lock, and says so (sanitized builds take a while).
    CHECK(said(messages, "waiting for another run writing '" + out + "'"));
    usleep(300000);
    CHECK(waitpid(run, nullptr, WNOHANG) == 0);  // still waiting
    CHECK_FALSE(std::filesystem::exists(out));
  }
  CHECK(exit_code(run) == 0);
  CHECK(features_read(out) > 100);
  CHECK_FALSE(std::filesystem::exists(dir / ".held.shp.lock"));
}

TEST_CASE("a run waiting for another run's lock stops on a signal, writing nothing",
          "[io][concurrency][interrupt]") {
  ScratchDir dir("held_stopped");
  const std::string out = dir / "held.gpkg", messages = dir / "messages.txt";
  const io::DestinationLock held(out);
  const pid_t run = start_cli({"silhouettes", kSample, out}, messages);
  REQUIRE(said(messages, "waiting for another run writing"));
  kill(run, SIGTERM);
  CHECK(exit_code(run) == 130);
  CHECK(slurp(messages).find("interrupted; no output written") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(staging_of(dir.path, run).empty());
}

TEST_CASE("the outputs of a run killed before its commit are all the earlier run's",
          "[io][concurrency]") {
  // A run writes strokes, statistics and a preview; a second run of another view is held at its
  // commit (this test holds the strokes' lock) and killed outright: not one of the three may be
  // the second run's.
  ScratchDir dir("one_commit");
  const std::string out = dir / "o.gpkg", stats = dir / "s.json", preview = dir / "p.png";
  const auto run_args = [&](const char* azimuth) {
    return std::vector<std::string>{"silhouettes", kSample,        out,
                                    "--azimuth",   azimuth,        "--preview",
                                    preview,       "--stats-json", stats};
  };
  REQUIRE(run_cli(run_args("90")).code == 0);
  const std::string stats_before = slurp(stats), preview_before = slurp(preview);
  const long long strokes_before = features_read(out);
  pid_t run = 0;
  {
    const io::DestinationLock held(out);
    const std::string messages = dir / "messages.txt";
    run = start_cli(run_args("0"), messages);
    REQUIRE(said(messages, "waiting for another run writing"));  // every output staged
    kill(run, SIGKILL);
    CHECK(exit_code(run) == -1);
  }
  CHECK(slurp(stats) == stats_before);
  CHECK(slurp(preview) == preview_before);
  CHECK(features_read(out) == strokes_before);
  // The next run into the folder removes the dead run's staging folders, and writes all three.
  REQUIRE(run_cli(run_args("0")).code == 0);
  CHECK(slurp(stats) != stats_before);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path))
    CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
}

// The pages of the file open as `fd` that are dirty (written, not yet handed to writeback), from
// Linux's cachestat (6.5 on; its number is the same on every architecture); -1 where the kernel
// has no cachestat.
long long dirty_pages(int fd) {
  struct {
    std::uint64_t off, len;
  } range{0, 0};
  struct {
    std::uint64_t cache, dirty, writeback, evicted, recently_evicted;
  } stat{};
  constexpr long kCachestat = 451;
  if (syscall(kCachestat, fd, &range, &stat, 0) != 0) return -1;
  return static_cast<long long>(stat.dirty);
}

TEST_CASE("a file still being written has its dirty pages handed to writeback early", "[io]") {
  ScratchDir dir("writeback");
  const std::string path = dir / "strokes.gpkg";
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  REQUIRE(fd >= 0);
  const std::string block(1 << 20, 'x');
  for (int k = 0; k < 16; ++k) REQUIRE(::write(fd, block.data(), block.size()) == 1 << 20);
  struct statfs where {};
  REQUIRE(fstatfs(fd, &where) == 0);
  constexpr long kTmpfs = 0x01021994;  // tmpfs keeps pages in memory: nothing to write back
  const long long dirty_before = dirty_pages(fd);
  if (dirty_before < 0 || where.f_type == kTmpfs) {
    WARN("no cachestat or a tmpfs here: only the refusal below is checked");
  } else {
    // The kernel writes a file back 30 s after it was dirtied, or when a tenth of memory is dirty.
    REQUIRE(dirty_before > 0);
    io::EarlyWriteback writeback(path);
    REQUIRE(writeback.start());
    // Started, the writeback ends within seconds; untouched, the pages would stay dirty.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (dirty_pages(fd) > 0 && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    CHECK(dirty_pages(fd) == 0);
  }
  ::close(fd);
  // A file it cannot open is left to the kernel, without an error.
  io::EarlyWriteback missing(dir / "no such file");
  CHECK_FALSE(missing.start());
}

TEST_CASE("an output replaces every file of the earlier one, side files included", "[io]") {
  ScratchDir dir("replace");
  const std::string shp = dir / "a.shp";
  REQUIRE(run_cli({"silhouettes", kSample, shp, "--azimuth", "0"}).code == 0);
  // A spatial index built on the earlier strokes, and side files other programs keep.
  {
    GDALAllRegister();
    io::DatasetPtr ds(static_cast<GDALDataset*>(
        GDALOpenEx(shp.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr)));
    REQUIRE(ds);
    ds->ExecuteSQL("CREATE SPATIAL INDEX ON a", nullptr, nullptr);
  }
  REQUIRE(std::filesystem::exists(dir / "a.qix"));
  for (const char* side : {"a.sbn", "a.sbx", "a.shp.xml", "a.qmd"})
    std::ofstream(dir / side) << "x";
  std::ofstream(dir / "another.qmd") << "not ours";
  REQUIRE(run_cli({"silhouettes", kSample, shp, "--azimuth", "90"}).code == 0);
  for (const char* side : {"a.qix", "a.sbn", "a.sbx", "a.shp.xml", "a.qmd"}) {
    CAPTURE(side);
    CHECK_FALSE(std::filesystem::exists(dir / side));
  }
  CHECK(std::filesystem::exists(dir / "another.qmd"));
  // A spatially filtered read finds every stroke.
  OGREnvelope everything;
  everything.MinX = everything.MinY = -1e12;
  everything.MaxX = everything.MaxY = 1e12;
  const long long all = features_read(shp);
  CHECK(all > 100);
  CHECK(features_read(shp, &everything) == all);
}

TEST_CASE("an output that names a file a VRT input reads is refused, the file kept", "[io]") {
  ScratchDir dir("vrt");
  const std::string src = dir / "src.tif", vrt = dir / "v_src.vrt";
  std::filesystem::copy_file(kSample, src);
  build_vrt(vrt, src);
  const auto before = std::filesystem::file_size(src);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"classify", vrt, src},
        std::vector<std::string>{"row-slope", vrt, src},
        std::vector<std::string>{"drape", kSample, src, "--source", vrt}}) {
    CAPTURE(args[0]);
    const CliRun run = run_cli(args);
    CHECK(run.code == 1);
    CHECK_THAT(run.err, Catch::Contains("names a file the"));
  }
  CHECK(std::filesystem::file_size(src) == before);
  CHECK(io::dataset_files(vrt).size() == 2);
}

TEST_CASE("an input that is a pipe or no file is refused before GDAL opens it", "[io]") {
  ScratchDir dir("pipe");
  const std::string pipe = dir / "dem.tif";
  REQUIRE(mkfifo(pipe.c_str(), 0600) == 0);
  const CliRun piped = run_cli({"silhouettes", pipe, dir / "o.gpkg"});
  CHECK(piped.code == 1);
  CHECK_THAT(piped.err, Catch::Contains("is not a file"));
  const CliRun missing = run_cli({"silhouettes", dir / "missing.tif", dir / "o.gpkg"});
  CHECK(missing.code == 1);
  CHECK_THAT(missing.err, Catch::Contains("No such file"));
  CHECK_NOTHROW(io::check_input_path("/vsizip/archive.zip/dem.tif"));
  CHECK_NOTHROW(io::check_input_path(dir.path.string()));  // a folder: an Arc/Info grid
}

TEST_CASE("clashes between outputs and inputs are found alike for every front end",
          "[io][robustness]") {
  ScratchDir dir("clashes");
  const double gt[6] = {500000, 10, 0, 4000000, 0, -10};
  write_tiff(
      dir / "src.tif", 8, 8, 1, [](int, int r, int c) { return r + c; }, gt, 32616);
  build_vrt(dir / "v.vrt", dir / "src.tif");
  const std::vector<io::NamedFile> inputs = {{"INPUT", dir / "v.vrt"}, {"--source", ""}};
  const auto clash = [&](std::vector<io::NamedFile> outputs) {
    return io::find_clash(outputs, inputs);
  };
  // An output over the VRT's source, by another spelling of its path.
  const auto source = clash({{"OUTPUT", dir / "./src.tif"}});
  REQUIRE(source);
  CHECK(source->with_input);
  CHECK(source->other.name == "INPUT");
  CHECK(io::same_file(source->file, dir / "src.tif"));
  CHECK(clash({{"OUTPUT", dir / "v.vrt"}}));
  // Two outputs over one file, unless both add a layer to it.
  const auto twice = clash({{"A", dir / "o.gpkg"}, {"B", dir / "o.gpkg"}});
  REQUIRE(twice);
  CHECK_FALSE(twice->with_input);
  CHECK(twice->output.name == "B");
  CHECK(twice->other.name == "A");
  CHECK_FALSE(clash({{"A", dir / "o.gpkg", false}, {"B", dir / "o.gpkg", false}}));
  CHECK(clash({{"A", dir / "o.gpkg", false}, {"B", dir / "o.gpkg", true}}));
  // Nothing shared, or nothing given: no clash.
  CHECK_FALSE(clash({{"OUTPUT", dir / "out.tif"}, {"--preview", ""}, {"--stats-json", ""}}));
}

TEST_CASE("a lock file planted as a link is refused, its target never made", "[io][robustness]") {
  ScratchDir dir("planted_lock");
  std::filesystem::create_directory(dir / "elsewhere");
  const std::string target = dir / "elsewhere/made_by_root";
  std::filesystem::create_symlink(target, dir / ".o.gpkg.lock");
  const CliRun run = run_cli({"silhouettes", kSample, dir / "o.gpkg"});
  CHECK(run.code == 1);
  CHECK_THAT(run.err, Catch::Contains("lock file is a symbolic link"));
  CHECK_THAT(run.err, Catch::Contains(".o.gpkg.lock"));
  CHECK_FALSE(std::filesystem::exists(target));
  CHECK_FALSE(std::filesystem::exists(dir / "o.gpkg"));
}

TEST_CASE("an output named as a member of another dataset is refused, the dataset kept",
          "[io][robustness]") {
  ScratchDir dir("member");
  REQUIRE(run_cli({"silhouettes", kSample, dir / "o.shp"}).code == 0);
  const std::size_t files = dir.file_count();
  // o.dbf is the shapefile's table: written as a GeoPackage, it took o.shp, .shx and .prj along.
  const CliRun run = run_cli({"silhouettes", kSample, dir / "o.dbf", "--format", "GPKG"});
  CHECK(run.code == 1);
  CHECK_THAT(run.err, Catch::Contains("is part of the dataset"));
  CHECK(dir.file_count() == files);
  CHECK(features_read(dir / "o.shp") > 100);
  // The shapefile itself is its own dataset: writing it again replaces it.
  CHECK(run_cli({"silhouettes", kSample, dir / "o.shp"}).code == 0);
}

TEST_CASE("a dataset replaced while it is checked is never taken for a member of another",
          "[io][concurrency]") {
  // Another run putting its output in place renames each file over the earlier one; a check
  // comparing the file GDAL lists with the named one by their inodes, read one after the other,
  // saw two files when a rename fell between the two reads.
  ScratchDir dir("replaced");
  REQUIRE(run_cli({"silhouettes", kSample, dir / "o.shp"}).code == 0);
  const std::filesystem::path shp = dir / "o.shp", first = dir / "first", second = dir / "second";
  std::filesystem::copy_file(shp, first);
  std::filesystem::copy_file(shp, second);
  std::atomic<bool> done{false};
  std::thread replacing([&] {
    for (unsigned k = 0; !done; ++k) {
      const std::filesystem::path next = dir / ".o.shp.next";
      if (::link(k % 2 ? first.c_str() : second.c_str(), next.c_str()) == 0)
        std::filesystem::rename(next, shp);
    }
  });
  std::size_t taken_for_member = 0;
  for (int k = 0; k < 4000; ++k) taken_for_member += !io::main_file_of_other_dataset(shp).empty();
  done = true;
  replacing.join();
  CHECK(taken_for_member == 0);
}

TEST_CASE("a VRT reading a named pipe is refused before GDAL hangs on it", "[io][robustness]") {
  ScratchDir dir("fifo_source");
  REQUIRE(mkfifo((dir / "pipe.tif").c_str(), 0600) == 0);
  std::ofstream(dir / "v.vrt") << R"(<VRTDataset rasterXSize="10" rasterYSize="10">
  <VRTRasterBand dataType="Float32" band="1">
    <SimpleSource><SourceFilename relativeToVRT="1">pipe.tif</SourceFilename>
      <SourceBand>1</SourceBand></SimpleSource>
  </VRTRasterBand>
</VRTDataset>)";
  // Before the check, the run sat in GDAL's open of the pipe and heard no SIGTERM.
  const pid_t run = start_cli({"classify", dir / "v.vrt", dir / "o.tif"});
  int status = 0;
  bool ended = false;
  for (int k = 0; k < 300 && !ended; ++k) {
    ended = waitpid(run, &status, WNOHANG) == run;
    if (!ended) usleep(50000);
  }
  if (!ended) {
    kill(run, SIGKILL);
    waitpid(run, &status, 0);
  }
  REQUIRE(ended);  // else the run below would hang too
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 1));
  const CliRun told = run_cli({"classify", dir / "v.vrt", dir / "o.tif"});
  CHECK_THAT(told.err, Catch::Contains("which is not a file (a pipe"));
  CHECK_FALSE(std::filesystem::exists(dir / "o.tif"));
}

TEST_CASE("a raster format that changes the values written fails the write, leaving nothing",
          "[io][robustness]") {
  // A GeoPackage keeps a paletted raster in PNG tiles, read back as 4 bands, or renumbered
  // (nodata 255 read back as 2); before its colour table reached 255, libpng refused the write
  // outright.
  ScratchDir dir("values");
  Grid<std::uint8_t> seen(40, 50, 0);
  for (std::size_t r = 0; r < 40; ++r)
    for (std::size_t c = 10; c < 50; ++c) seen(r, c) = c < 40 ? 1 : 255;
  GeoTransform gt;
  gt.a = {500000, 10, 0, 4000000, 0, -10};
  CHECK_THROWS_WITH(io::write_visibility(dir / "seen.gpkg", seen, gt, ""),
                    Catch::Contains("GPKG format") && Catch::Contains("use .tif"));
  CHECK(dir.file_count() == 0);
  io::write_visibility(dir / "seen.tif", seen, gt, "");
  io::DatasetPtr ds(static_cast<GDALDataset*>(GDALOpen((dir / "seen.tif").c_str(), GA_ReadOnly)));
  REQUIRE(ds);
  std::vector<std::uint8_t> read(40 * 50);
  REQUIRE(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 50, 40, read.data(), 50, 40, GDT_Byte, 0,
                                         0) == CE_None);
  CHECK(std::equal(read.begin(), read.end(), seen.data()));
}

TEST_CASE("text written as it is made reaches the file whole, or fails leaving nothing",
          "[io][robustness]") {
  ScratchDir dir("streamed_text");
  // Bytes counted by the stream's put position, across its buffer's drains: what a PDF's
  // cross-reference table is made of.
  std::string expected;
  std::vector<long long> offsets;
  const auto write = [&](std::ostream& out) {
    for (int k = 0; k < 20000; ++k) {
      offsets.push_back(static_cast<long long>(out.tellp()));
      const std::string line = std::to_string(k) + " 0 obj\n";
      out << line;
      expected += line;
    }
  };
  io::write_text_file(dir / "whole.txt", write);
  const std::string written = slurp(dir / "whole.txt");
  REQUIRE(written == expected);
  for (std::size_t k = 0; k < offsets.size(); k += 997)
    CHECK(written.compare(static_cast<std::size_t>(offsets[k]), std::to_string(k).size() + 6,
                          std::to_string(k) + " 0 obj") == 0);
  // A file size limit stands in for a full disk: the write past it fails with the reason, and
  // nothing is left, neither the file nor its staging.
  const std::string errors = dir / "errors.txt";
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const rlimit limit{8 * 1024, 8 * 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    std::signal(SIGXFSZ, SIG_IGN);
    try {
      io::write_text_file(dir / "cut.txt", [](std::ostream& out) {
        for (int k = 0; k < 100000; ++k) out << k << " 0 obj\n";
      });
    } catch (const Error& e) {
      std::ofstream(errors) << e.what();
      _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
  CHECK_THAT(slurp(errors), Catch::Contains("cut.txt") && Catch::Contains("File too large"));
  std::filesystem::remove(errors);
  CHECK(dir.file_count() == 1);  // whole.txt alone
}
