#include "io/pages/preview.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <locale>
#include <sstream>
#include <utility>
#include <vector>

#include "io/pages/ink_canvas.h"
#include "io/pages/sketch_page.h"
#include "io/pages/vector_art.h"
#include "io/read/gdal_util.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

// A paper page's pixels in a millimetre, at kPreviewDpi.
constexpr double kPixelsPerMm = kPreviewDpi / 25.4;

// GDAL's progress while it writes the picture: the last fifth of the work.
struct Encoding {
  const ProgressFn& progress;
  bool stopped = false;
};
int CPL_STDCALL encoding_progress(double fraction, const char*, void* data) {
  Encoding& encoding = *static_cast<Encoding*>(data);
  encoding.stopped = encoding.progress && !encoding.progress(0.8 + 0.2 * fraction);
  return encoding.stopped ? FALSE : TRUE;
}

// Draws the page's paths, `scale` pixels to a page unit, formulated first so factual strokes
// stay on top, and the labels' leaders: a picture has no text, so its peaks show as leaders alone.
void draw_page(InkCanvas& canvas, const SketchPage& page, double scale,
               const ProgressFn& progress) {
  std::size_t drawn = 0;
  const double total = 2.0 * static_cast<double>(std::max<std::size_t>(1, page.paths.size()));
  for (StrokeClass cls : {StrokeClass::formulated, StrokeClass::factual}) {
    const bool factual = cls == StrokeClass::factual;
    for (const PagePath& s : page.paths) {
      if (++drawn % 256 == 0) tell_progress(progress, 0.8 * static_cast<double>(drawn) / total);
      if (s.cls != cls) continue;
      for (std::size_t k = 1; k < s.points.size(); ++k) {
        // Each width scaled before the sum, as when the page itself was scaled: the same pixels.
        const double radius = 0.25 * (s.widths[k - 1] * scale + s.widths[k] * scale);
        canvas.line(s.points[k - 1].x * scale, s.points[k - 1].y * scale, s.points[k].x * scale,
                    s.points[k].y * scale, radius,
                    static_cast<float>(s.ink) * (factual ? 1.f : 0.6f));
      }
    }
  }
  for (const PageLabel& l : page.labels)
    canvas.line(l.from.x * scale, l.from.y * scale, l.to.x * scale, l.to.y * scale, 0.5, 0.5f);
  tell_progress(progress, 0.8);
}

// The page drawn scaled on a canvas, not copied: a page of a million paths is a gigabyte.
void write_png_preview(const std::string& path, const SketchPage& page,
                       const ProgressFn& progress) {
  const double scale = page.millimetres ? kPixelsPerMm : 1.0;
  const double pixels_across = page.millimetres ? std::ceil(page.width * scale) : page.width;
  const double pixels_down = page.millimetres ? std::ceil(page.height * scale) : page.height;
  check_png_pixels(pixels_across, pixels_down);
  InkCanvas canvas(static_cast<int>(pixels_across), static_cast<int>(pixels_down));
  draw_page(canvas, page, scale, progress);
  GDALAllRegister();
  GdalErrorCapture capture;
  std::vector<std::uint8_t> pixels = canvas.pixels();
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
  if (!mem || !png) throw Error("GDAL has no MEM or PNG driver");
  const int width = canvas.width(), height = canvas.height();
  DatasetPtr image(mem->Create("", width, height, 1, GDT_Byte, nullptr));
  if (!image || image->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, width, height, pixels.data(),
                                                  width, height, GDT_Byte, 0, 0) != CE_None) {
    throw Error("cannot draw the preview: " + capture.message());
  }
  write_atomically(path, [&](const std::filesystem::path& staged) {
    Encoding encoding{progress};
    DatasetPtr out(
        png->CreateCopy(staged.c_str(), image.get(), FALSE, nullptr, encoding_progress, &encoding));
    if (encoding.stopped) throw Cancelled();
    if (!out) throw Error("cannot write preview '" + path + "': " + capture.message());
  });
}

}  // namespace

void check_png_pixels(double width, double height) {
  if (width * height <= kMaxPreviewPixels) return;
  throw Error("a PNG preview of " + number_text(width) + " x " + number_text(height) +
              " pixels would take " + number_text(std::ceil(width * height * 6 / 1e9)) +
              " GB to draw; the most is " + number_text(kMaxPreviewPixels / 1e6) +
              " million pixels (" + number_text(std::floor(std::sqrt(kMaxPreviewPixels))) +
              " squared): give a smaller --page, or a .svg or .pdf preview");
}

void check_png_page(const PageSize& size) {
  check_png_pixels(std::ceil(size.width_mm * kPixelsPerMm),
                   std::ceil(size.height_mm * kPixelsPerMm));
}

PlotterReport write_page(const std::string& path, const SketchPage& page,
                         const PageOptions& options, const ProgressFn& progress) {
  const std::string ext = lowercase_extension(path);
  if (options.plotter && ext == ".png")
    throw Error("--plotter draws vector art for a pen: give --preview a .svg or .pdf name");
  if (ext == ".png") {
    write_png_preview(path, page, progress);
    return {};
  }
  PlotterPage plotter;
  if (options.plotter) plotter = plan_plotter_page(page);
  const PlotterPage* pen = options.plotter ? &plotter : nullptr;
  if (ext == ".pdf") {
    write_pdf(path, page, pen);
  } else {
    write_svg(path, page, pen);
  }
  return plotter.report;
}

}  // namespace tsk::io
