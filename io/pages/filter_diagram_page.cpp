#include "io/pages/filter_diagram_page.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace tsk {
namespace {

// `text` safe inside HTML: a file name may hold '<' or '&'.
std::string html_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else if (c == '&') {
      out += "&amp;";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string filter_diagram_html(const SlopeScatter& s, const FilterParams& filter,
                                const std::string& raw_title) {
  const std::string title = html_text(raw_title);
  const double size = 560, margin = 60;
  const double scale = size / s.max_pct;
  auto x = [&](double col_pct) { return margin + col_pct * scale; };
  auto y = [&](double row_pct) { return margin + size - row_pct * scale; };
  const double cell = size / s.bins;
  std::size_t all = 0, candidate = 0, filtered = 0;
  for (std::size_t k = 0; k < s.all.size(); ++k) {
    all += s.all[k], candidate += s.candidate[k], filtered += s.filtered[k];
  }
  std::ostringstream o;
  o.precision(4);
  o << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << title
    << "</title></head>\n<body style=\"font-family:sans-serif\">\n<h2>" << title << "</h2>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size + 2 * margin << "\" height=\""
    << size + 2 * margin << "\">\n"
    << "<rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << size << "\" height=\""
    << size << "\" fill=\"white\" stroke=\"black\"/>\n";
  // The removal region: filled under the points, outlined over them.
  std::ostringstream corners;
  corners.precision(4);
  const double corner_col = filter.diagonals ? filter.ctrl_col_pct : filter.col_cut_pct;
  const double corner_row = filter.diagonals ? filter.ctrl_row_pct() : filter.row_cut_pct;
  corners << x(0) << "," << y(0) << " " << x(filter.col_cut_pct) << "," << y(0) << " "
          << x(corner_col) << "," << y(corner_row) << " " << x(0) << "," << y(filter.row_cut_pct);
  o << "<polygon id=\"removal\" fill=\"#cccccc\" fill-opacity=\"0.6\" points=\"" << corners.str()
    << "\"/>\n";
  // Bins: opacity grows with the log of the count; c-set red, f-set black on top.
  const std::vector<std::size_t>* layers[] = {&s.all, &s.candidate, &s.filtered};
  const char* colours[] = {"#999999", "#d62020", "#000000"};
  for (int layer = 0; layer < 3; ++layer) {
    const auto& counts = *layers[layer];
    const double top =
        std::log1p(static_cast<double>(*std::max_element(counts.begin(), counts.end())));
    for (int r = 0; r < s.bins; ++r) {
      for (int c = 0; c < s.bins; ++c) {
        const std::size_t n = counts[static_cast<std::size_t>(r * s.bins + c)];
        if (n == 0) continue;
        o << "<rect x=\"" << margin + c * cell << "\" y=\"" << margin + size - (r + 1) * cell
          << "\" width=\"" << cell << "\" height=\"" << cell << "\" fill=\"" << colours[layer]
          << "\" fill-opacity=\"" << 0.25 + 0.75 * std::log1p(static_cast<double>(n)) / top
          << "\"/>\n";
      }
    }
  }
  o << "<polygon fill=\"none\" stroke=\"#0050c8\" stroke-width=\"1.5\" points=\"" << corners.str()
    << "\"/>\n";
  o << "<circle id=\"control\" cx=\"" << x(filter.ctrl_col_pct) << "\" cy=\""
    << y(filter.ctrl_row_pct())
    << "\" r=\"4\" fill=\"none\" stroke=\"blue\" stroke-width=\"2\"/>\n";
  for (int t = 0; t <= 4; ++t) {
    const double v = s.max_pct * t / 4;
    o << "<text x=\"" << x(v) << "\" y=\"" << margin + size + 18 << "\" text-anchor=\"middle\">"
      << v << "</text><text x=\"" << margin - 8 << "\" y=\"" << y(v) + 4
      << "\" text-anchor=\"end\">" << v << "</text>\n";
  }
  o << "<text x=\"" << margin + size / 2 << "\" y=\"" << margin + size + 42
    << "\" text-anchor=\"middle\">|column slope| along the view (%)</text>\n"
    << "<text transform=\"translate(16," << margin + size / 2
    << ") rotate(-90)\" text-anchor=\"middle\">|row slope| across the view (%)</text>\n</svg>\n"
    << "<p>Grey: all cells with a column slope (" << all << "). Red: the c-set (" << candidate
    << "). Black: the f-set, c-set cells the filter keeps (" << filtered
    << "). Grey area outlined in blue: removed by the filter (row cut-off " << filter.row_cut_pct
    << " %, column cut-off " << filter.col_cut_pct << " %, control point (" << filter.ctrl_col_pct
    << " %, " << filter.ctrl_row_pct() << " %)" << (filter.diagonals ? "" : ", no diagonals")
    << "). Blue circle: the control point.</p>\n</body></html>\n";
  return o.str();
}

}  // namespace tsk
