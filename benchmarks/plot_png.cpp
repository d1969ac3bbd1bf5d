#include "plot_png.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace prism::bench {
namespace {

// The classic 5x7 LCD font, ASCII 32..126: five column bytes per glyph, bit 0
// the top row.
const std::uint8_t kFont[95][5] = {
    {0x00, 0x00, 0x00, 0x00, 0x00}, {0x00, 0x00, 0x5F, 0x00, 0x00}, {0x00, 0x07, 0x00, 0x07, 0x00},
    {0x14, 0x7F, 0x14, 0x7F, 0x14}, {0x24, 0x2A, 0x7F, 0x2A, 0x12}, {0x23, 0x13, 0x08, 0x64, 0x62},
    {0x36, 0x49, 0x55, 0x22, 0x50}, {0x00, 0x05, 0x03, 0x00, 0x00}, {0x00, 0x1C, 0x22, 0x41, 0x00},
    {0x00, 0x41, 0x22, 0x1C, 0x00}, {0x08, 0x2A, 0x1C, 0x2A, 0x08}, {0x08, 0x08, 0x3E, 0x08, 0x08},
    {0x00, 0x50, 0x30, 0x00, 0x00}, {0x08, 0x08, 0x08, 0x08, 0x08}, {0x00, 0x60, 0x60, 0x00, 0x00},
    {0x20, 0x10, 0x08, 0x04, 0x02}, {0x3E, 0x51, 0x49, 0x45, 0x3E}, {0x00, 0x42, 0x7F, 0x40, 0x00},
    {0x42, 0x61, 0x51, 0x49, 0x46}, {0x21, 0x41, 0x45, 0x4B, 0x31}, {0x18, 0x14, 0x12, 0x7F, 0x10},
    {0x27, 0x45, 0x45, 0x45, 0x39}, {0x3C, 0x4A, 0x49, 0x49, 0x30}, {0x01, 0x71, 0x09, 0x05, 0x03},
    {0x36, 0x49, 0x49, 0x49, 0x36}, {0x06, 0x49, 0x49, 0x29, 0x1E}, {0x00, 0x36, 0x36, 0x00, 0x00},
    {0x00, 0x56, 0x36, 0x00, 0x00}, {0x00, 0x08, 0x14, 0x22, 0x41}, {0x14, 0x14, 0x14, 0x14, 0x14},
    {0x41, 0x22, 0x14, 0x08, 0x00}, {0x02, 0x01, 0x51, 0x09, 0x06}, {0x32, 0x49, 0x79, 0x41, 0x3E},
    {0x7E, 0x11, 0x11, 0x11, 0x7E}, {0x7F, 0x49, 0x49, 0x49, 0x36}, {0x3E, 0x41, 0x41, 0x41, 0x22},
    {0x7F, 0x41, 0x41, 0x22, 0x1C}, {0x7F, 0x49, 0x49, 0x49, 0x41}, {0x7F, 0x09, 0x09, 0x01, 0x01},
    {0x3E, 0x41, 0x41, 0x51, 0x32}, {0x7F, 0x08, 0x08, 0x08, 0x7F}, {0x00, 0x41, 0x7F, 0x41, 0x00},
    {0x20, 0x40, 0x41, 0x3F, 0x01}, {0x7F, 0x08, 0x14, 0x22, 0x41}, {0x7F, 0x40, 0x40, 0x40, 0x40},
    {0x7F, 0x02, 0x04, 0x02, 0x7F}, {0x7F, 0x04, 0x08, 0x10, 0x7F}, {0x3E, 0x41, 0x41, 0x41, 0x3E},
    {0x7F, 0x09, 0x09, 0x09, 0x06}, {0x3E, 0x41, 0x51, 0x21, 0x5E}, {0x7F, 0x09, 0x19, 0x29, 0x46},
    {0x46, 0x49, 0x49, 0x49, 0x31}, {0x01, 0x01, 0x7F, 0x01, 0x01}, {0x3F, 0x40, 0x40, 0x40, 0x3F},
    {0x1F, 0x20, 0x40, 0x20, 0x1F}, {0x7F, 0x20, 0x18, 0x20, 0x7F}, {0x63, 0x14, 0x08, 0x14, 0x63},
    {0x03, 0x04, 0x78, 0x04, 0x03}, {0x61, 0x51, 0x49, 0x45, 0x43}, {0x00, 0x00, 0x7F, 0x41, 0x41},
    {0x02, 0x04, 0x08, 0x10, 0x20}, {0x41, 0x41, 0x7F, 0x00, 0x00}, {0x04, 0x02, 0x01, 0x02, 0x04},
    {0x40, 0x40, 0x40, 0x40, 0x40}, {0x00, 0x01, 0x02, 0x04, 0x00}, {0x20, 0x54, 0x54, 0x54, 0x78},
    {0x7F, 0x48, 0x44, 0x44, 0x38}, {0x38, 0x44, 0x44, 0x44, 0x20}, {0x38, 0x44, 0x44, 0x48, 0x7F},
    {0x38, 0x54, 0x54, 0x54, 0x18}, {0x08, 0x7E, 0x09, 0x01, 0x02}, {0x08, 0x14, 0x54, 0x54, 0x3C},
    {0x7F, 0x08, 0x04, 0x04, 0x78}, {0x00, 0x44, 0x7D, 0x40, 0x00}, {0x20, 0x40, 0x44, 0x3D, 0x00},
    {0x00, 0x7F, 0x10, 0x28, 0x44}, {0x00, 0x41, 0x7F, 0x40, 0x00}, {0x7C, 0x04, 0x18, 0x04, 0x78},
    {0x7C, 0x08, 0x04, 0x04, 0x78}, {0x38, 0x44, 0x44, 0x44, 0x38}, {0x7C, 0x14, 0x14, 0x14, 0x08},
    {0x08, 0x14, 0x14, 0x18, 0x7C}, {0x7C, 0x08, 0x04, 0x04, 0x08}, {0x48, 0x54, 0x54, 0x54, 0x20},
    {0x04, 0x3F, 0x44, 0x40, 0x20}, {0x3C, 0x40, 0x40, 0x20, 0x7C}, {0x1C, 0x20, 0x40, 0x20, 0x1C},
    {0x3C, 0x40, 0x30, 0x40, 0x3C}, {0x44, 0x28, 0x10, 0x28, 0x44}, {0x0C, 0x50, 0x50, 0x50, 0x3C},
    {0x44, 0x64, 0x54, 0x4C, 0x44}, {0x00, 0x08, 0x36, 0x41, 0x00}, {0x00, 0x00, 0x7F, 0x00, 0x00},
    {0x00, 0x41, 0x36, 0x08, 0x00}, {0x08, 0x04, 0x08, 0x10, 0x08},
};

struct Rgb {
  std::uint8_t r, g, b;
};

// Colour-blind-safe palette (Okabe and Ito), for series without their own colour.
const Rgb kPalette[] = {{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167},
                        {230, 159, 0}, {86, 180, 233}, {0, 0, 0}, {120, 120, 120}};

class Canvas {
 public:
  Canvas(int w, int h) : m_w(w), m_h(h), m_px(static_cast<std::size_t>(w) * h * 3, 255) {}
  int width() const { return m_w; }
  int height() const { return m_h; }
  std::vector<std::uint8_t>& pixels() { return m_px; }

  void set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= m_w || y >= m_h) return;
    std::uint8_t* p = &m_px[(static_cast<std::size_t>(y) * m_w + x) * 3];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
  void fill(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) set(x, y, c);
  }
  // A line `thick` pixels wide (a square brush along Bresenham's path).
  void line(double xa, double ya, double xb, double yb, Rgb c, int thick = 1, int dash = 0) {
    int x0 = static_cast<int>(std::lround(xa)), y0 = static_cast<int>(std::lround(ya));
    int x1 = static_cast<int>(std::lround(xb)), y1 = static_cast<int>(std::lround(yb));
    int dx = std::abs(x1 - x0), sx = x0 < x1 ? 1 : -1, dy = -std::abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
    int err = dx + dy, step = 0;
    const int lo = -(thick - 1) / 2, hi = thick / 2;
    for (;;) {
      if (dash == 0 || (step / dash) % 2 == 0) fill(x0 + lo, y0 + lo, x0 + hi, y0 + hi, c);
      ++step;
      if (x0 == x1 && y0 == y1) break;
      int e2 = 2 * err;
      if (e2 >= dy) {
        err += dy;
        x0 += sx;
      }
      if (e2 <= dx) {
        err += dx;
        y0 += sy;
      }
    }
  }
  // Text at (x, y) top-left, `scale` pixels per font dot; vertical runs bottom to top.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1, bool vertical = false) {
    int pen = 0;
    for (char ch : s) {
      int g = (ch < 32 || ch > 126) ? '?' - 32 : ch - 32;
      for (int col = 0; col < 5; ++col)
        for (int row = 0; row < 7; ++row)
          if (kFont[g][col] >> row & 1) {
            int u = pen + col * scale, v = row * scale;
            for (int a = 0; a < scale; ++a)
              for (int b = 0; b < scale; ++b) {
                if (vertical)
                  set(x + v + b, y - u - a, c);
                else
                  set(x + u + a, y + v + b, c);
              }
          }
      pen += 6 * scale;
    }
  }
  static int textWidth(const std::string& s, int scale = 1) { return static_cast<int>(s.size()) * 6 * scale; }

 private:
  int m_w, m_h;
  std::vector<std::uint8_t> m_px;
};

// 1, 10, 100, 1k, 10k, ... 1M, or 0.01 for small decades.
std::string decadeLabel(int e) {
  static const char* big[] = {"1", "10", "100", "1k", "10k", "100k", "1M", "10M", "100M", "1G"};
  if (e >= 0 && e <= 9) return big[e];
  char buf[16];
  std::snprintf(buf, sizeof buf, "1e%d", e);
  return buf;
}

}  // namespace

std::vector<std::uint8_t> renderLogLogPlot(const std::string& title, const std::string& x_label,
                                           const std::string& y_label, const std::vector<PlotSeries>& series,
                                           const std::vector<std::string>& notes, int* width, int* height) {
  const int W = 900, H = 600, left = 90, right = 190, top = 50, bottom = 70;
  Canvas cv(W, H);
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  auto usable = [](std::pair<double, double> p) {
    return p.first > 0 && p.second > 0 && std::isfinite(p.first) && std::isfinite(p.second);
  };
  for (const PlotSeries& s : series)
    for (const auto* list : {&s.line, &s.markers})
      for (auto p : *list)
        if (usable(p)) {
          xmin = std::min(xmin, p.first);
          xmax = std::max(xmax, p.first);
          ymin = std::min(ymin, p.second);
          ymax = std::max(ymax, p.second);
        }
  if (!(xmin <= xmax)) xmin = 1, xmax = 10, ymin = 1, ymax = 10;
  // Whole decades around the data.
  int ex0 = static_cast<int>(std::floor(std::log10(xmin))), ex1 = static_cast<int>(std::ceil(std::log10(xmax)));
  int ey0 = static_cast<int>(std::floor(std::log10(ymin))), ey1 = static_cast<int>(std::ceil(std::log10(ymax)));
  if (ex1 == ex0) ++ex1;
  if (ey1 == ey0) ++ey1;
  const double pw = W - left - right, ph = H - top - bottom;
  auto px = [&](double x) { return left + (std::log10(x) - ex0) / (ex1 - ex0) * pw; };
  auto py = [&](double y) { return top + ph - (std::log10(y) - ey0) / (ey1 - ey0) * ph; };
  const Rgb grid{225, 225, 225}, minor{242, 242, 242}, ink{0, 0, 0};

  for (int e = ex0; e < ex1; ++e)
    for (int m = 2; m < 10; ++m) cv.line(px(m * std::pow(10.0, e)), top, px(m * std::pow(10.0, e)), top + ph, minor);
  for (int e = ey0; e < ey1; ++e)
    for (int m = 2; m < 10; ++m) cv.line(left, py(m * std::pow(10.0, e)), left + pw, py(m * std::pow(10.0, e)), minor);
  for (int e = ex0; e <= ex1; ++e) {
    double x = px(std::pow(10.0, e));
    cv.line(x, top, x, top + ph, grid);
    std::string l = decadeLabel(e);
    cv.text(static_cast<int>(x) - Canvas::textWidth(l, 2) / 2, top + static_cast<int>(ph) + 8, l, ink, 2);
  }
  for (int e = ey0; e <= ey1; ++e) {
    double y = py(std::pow(10.0, e));
    cv.line(left, y, left + pw, y, grid);
    std::string l = e < 0 ? decadeLabel(e) : decadeLabel(e);
    cv.text(left - 8 - Canvas::textWidth(l, 2), static_cast<int>(y) - 7, l, ink, 2);
  }
  cv.line(left, top, left + pw, top, ink);
  cv.line(left, top + ph, left + pw, top + ph, ink);
  cv.line(left, top, left, top + ph, ink);
  cv.line(left + pw, top, left + pw, top + ph, ink);

  cv.text(W / 2 - Canvas::textWidth(title, 2) / 2, 14, title, ink, 2);
  cv.text(left + static_cast<int>(pw) / 2 - Canvas::textWidth(x_label, 2) / 2, H - 30, x_label, ink, 2);
  cv.text(18, top + static_cast<int>(ph) / 2 + Canvas::textWidth(y_label, 2) / 2, y_label, ink, 2, true);

  int next_colour = 0;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& s = series[i];
    Rgb c = s.color >= 0 ? Rgb{static_cast<std::uint8_t>(s.color >> 16), static_cast<std::uint8_t>(s.color >> 8),
                               static_cast<std::uint8_t>(s.color)}
                         : kPalette[next_colour++ % (sizeof kPalette / sizeof kPalette[0])];
    std::vector<std::pair<double, double>> pts;
    for (auto p : s.line)
      if (usable(p)) pts.push_back(p);
    std::sort(pts.begin(), pts.end());
    for (std::size_t k = 1; k < pts.size(); ++k)
      cv.line(px(pts[k - 1].first), py(pts[k - 1].second), px(pts[k].first), py(pts[k].second), c, 3);
    for (auto p : pts) {
      int x = static_cast<int>(std::lround(px(p.first))), y = static_cast<int>(std::lround(py(p.second)));
      cv.fill(x - 4, y - 4, x + 4, y + 4, c);
    }
    for (auto p : s.markers) {
      if (!usable(p)) continue;
      int x = static_cast<int>(std::lround(px(p.first))), y = static_cast<int>(std::lround(py(p.second)));
      cv.line(x - 5, y - 5, x + 5, y - 5, c, 2);
      cv.line(x + 5, y - 5, x + 5, y + 5, c, 2);
      cv.line(x + 5, y + 5, x - 5, y + 5, c, 2);
      cv.line(x - 5, y + 5, x - 5, y - 5, c, 2);
    }
    int ly = top + 10 + static_cast<int>(i) * 26;
    cv.line(left + pw + 16, ly + 7, left + pw + 46, ly + 7, c, 3);
    cv.fill(static_cast<int>(left + pw) + 27, ly + 3, static_cast<int>(left + pw) + 35, ly + 11, c);
    cv.text(static_cast<int>(left + pw) + 54, ly, s.name, ink, 2);
  }
  const int note_y = top + 20 + static_cast<int>(series.size()) * 26;
  for (std::size_t k = 0; k < notes.size(); ++k)
    cv.text(static_cast<int>(left + pw) + 14, note_y + 12 * static_cast<int>(k), notes[k], ink, 1);
  *width = W;
  *height = H;
  return std::move(cv.pixels());
}

void writeLogLogPlot(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series,
                     const std::vector<std::string>& notes) {
  int w = 0, h = 0;
  std::vector<std::uint8_t> px = renderLogLogPlot(title, x_label, y_label, series, notes, &w, &h);
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write PNG: " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, px.data()) || !out->close())
    throw std::runtime_error(path + ": cannot write PNG: " + out->geterror());
}

}  // namespace prism::bench
