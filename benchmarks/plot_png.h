// Log-log line charts for prism-bench, drawn by a small rasteriser (lines,
// markers, a 5x7 bitmap font) and written as PNG through OpenImageIO, so the
// benchmark needs no plotting package.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace prism::bench {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> line;     // (x, y) joined by a line, in x order
  std::vector<std::pair<double, double>> markers;  // (x, y) drawn as open squares only
  // 0xRRGGBB, or -1 for the next colour of the palette.
  long color = -1;
};

// One line (and markers) per series with a legend, decade grid lines and
// labels; points with x or y not finite and positive are skipped. `notes` are
// small lines under the legend, where the caller says what its lines and
// squares stand for. Throws std::runtime_error naming the path when the file
// cannot be written.
void writeLogLogPlot(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series,
                     const std::vector<std::string>& notes);

// The plot as RGB8 pixels (row-major, top row first), for tests and callers
// that write elsewhere.
std::vector<std::uint8_t> renderLogLogPlot(const std::string& title, const std::string& x_label,
                                           const std::string& y_label, const std::vector<PlotSeries>& series,
                                           const std::vector<std::string>& notes,
                                           int* width, int* height);

}  // namespace prism::bench
