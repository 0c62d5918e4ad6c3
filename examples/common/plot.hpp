// Pictures for the examples: SVG line plots (loss curves, 1D fields against
// targets) and PNG images of 2D fields (a diverging colour map). No
// dependencies: the PNG is written with stored (uncompressed) deflate blocks.
// Files are written to a temporary name and renamed, so a picture is either
// complete or absent.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dpgen_examples {

struct Series {
  std::string name;
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dashed = false;
};

inline void write_atomically(const std::string& path, const std::string& bytes) {
  std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f)
      throw std::runtime_error("cannot write " + tmp);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!f)
      throw std::runtime_error("write failed: " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename " + tmp + " to " + path);
}

/// A line plot with axes, ticks and a legend. log_y plots log10(y).
inline void write_svg_plot(const std::string& path, const std::string& title,
                           const std::string& xlabel, const std::string& ylabel,
                           const std::vector<Series>& series, bool log_y = false) {
  const double W = 720, H = 440, L = 80, R = 20, T = 40, B = 60;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  auto ty = [&](double y) { return log_y ? std::log10(std::max(y, 1e-300)) : y; };
  for (const auto& s : series)
    for (size_t i = 0; i < s.x.size(); ++i) {
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, ty(s.y[i])), y1 = std::max(y1, ty(s.y[i]));
    }
  if (!(x1 > x0))
    x1 = x0 + 1;
  if (!(y1 > y0))
    y1 = y0 + 1;
  double pad = 0.05 * (y1 - y0);
  y0 -= pad, y1 += pad;
  auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  auto py = [&](double y) { return H - B - (ty(y) - y0) / (y1 - y0) * (H - T - B); };
  auto pyv = [&](double v) { return H - B - (v - y0) / (y1 - y0) * (H - T - B); };
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' "
       "fill='white'/>\n";
  o << "<text x='" << W / 2 << "' y='22' text-anchor='middle' font-size='15'>" << title
    << "</text>\n";
  o << "<rect x='" << L << "' y='" << T << "' width='" << W - L - R << "' height='" << H - T - B
    << "' fill='none' stroke='black'/>\n";
  auto num = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", std::fabs(v) < 1e-12 ? 0.0 : v);
    return std::string(buf);
  };
  for (int k = 0; k <= 5; ++k) {
    double xv = x0 + (x1 - x0) * k / 5;
    o << "<line x1='" << px(xv) << "' y1='" << H - B << "' x2='" << px(xv) << "' y2='" << H - B + 5
      << "' stroke='black'/><text x='" << px(xv) << "' y='" << H - B + 18
      << "' text-anchor='middle'>" << num(xv) << "</text>\n";
  }
  // y ticks: every decade on a log axis, six even steps otherwise.
  std::vector<std::pair<double, std::string>> yticks;
  if (log_y) {
    int step = std::max(1, static_cast<int>(std::ceil((y1 - y0) / 8)));
    for (int e = static_cast<int>(std::ceil(y0)); e <= y1; e += step)
      yticks.push_back({double(e), "1e" + std::to_string(e)});
  } else {
    for (int k = 0; k <= 5; ++k)
      yticks.push_back({y0 + (y1 - y0) * k / 5, num(y0 + (y1 - y0) * k / 5)});
  }
  for (const auto& [yv, lab] : yticks)
    o << "<line x1='" << L - 5 << "' y1='" << pyv(yv) << "' x2='" << L << "' y2='" << pyv(yv)
      << "' stroke='black'/><text x='" << L - 8 << "' y='" << pyv(yv) + 4
      << "' text-anchor='end'>" << lab << "</text>\n";
  o << "<text x='" << (L + W - R) / 2 << "' y='" << H - 15 << "' text-anchor='middle'>" << xlabel
    << "</text>\n";
  o << "<text x='18' y='" << (T + H - B) / 2 << "' text-anchor='middle' transform='rotate(-90 18 "
    << (T + H - B) / 2 << ")'>" << ylabel << (log_y ? " (log scale)" : "") << "</text>\n";
  int row = 0;
  for (const auto& s : series) {
    o << "<polyline fill='none' stroke='" << s.color << "' stroke-width='1.8'"
      << (s.dashed ? " stroke-dasharray='6,4'" : "") << " points='";
    for (size_t i = 0; i < s.x.size(); ++i)
      o << px(s.x[i]) << "," << py(s.y[i]) << " ";
    o << "'/>\n";
    double ly = T + 16 + 16 * row++;
    o << "<line x1='" << W - R - 150 << "' y1='" << ly << "' x2='" << W - R - 125 << "' y2='" << ly
      << "' stroke='" << s.color << "' stroke-width='2'" << (s.dashed ? " stroke-dasharray='6,4'" : "")
      << "/><text x='" << W - R - 120 << "' y='" << ly + 4 << "'>" << s.name << "</text>\n";
  }
  o << "</svg>\n";
  write_atomically(path, o.str());
}

namespace detail {
inline uint32_t crc32(const std::string& s) {
  static std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k)
        c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xffffffffu;
  for (unsigned char b : s)
    c = table[(c ^ b) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}
inline void be32(std::string& s, uint32_t v) {
  for (int k = 3; k >= 0; --k)
    s.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}
inline void chunk(std::string& png, const char* type, const std::string& data) {
  be32(png, static_cast<uint32_t>(data.size()));
  std::string body = std::string(type, 4) + data;
  png += body;
  be32(png, crc32(body));
}
} // namespace detail

/// 2D fields (row-major, nx by ny, row 0 at the bottom) side by side in one
/// PNG, separated by a grey gap, each cell `scale` pixels wide; blue
/// (negative) - white - red (positive), one symmetric scale for all panels
/// (`magnitude`, or 0 for the largest |value|).
inline void write_png_panels(const std::string& path, const std::vector<std::vector<double>>& fs,
                             int nx, int ny, int scale = 4, double magnitude = 0) {
  for (const auto& f : fs)
    if (f.size() != size_t(nx) * size_t(ny))
      throw std::invalid_argument("write_png_panels: field has " + std::to_string(f.size()) +
                                  " values, expected " + std::to_string(nx * ny));
  if (magnitude <= 0)
    for (const auto& f : fs)
      for (double v : f)
        magnitude = std::max(magnitude, std::fabs(v));
  if (magnitude <= 0)
    magnitude = 1;
  const int gap = 2 * scale, panel = nx * scale;
  const int w = static_cast<int>(fs.size()) * (panel + gap) - gap, h = ny * scale;
  std::string raw;
  raw.reserve(size_t(h) * (1 + 3 * size_t(w)));
  for (int y = h - 1; y >= 0; --y) {
    raw.push_back(0); // filter: none
    for (int x = 0; x < w; ++x) {
      auto c = [](double t) { return static_cast<char>(static_cast<int>(255 * t + 0.5)); };
      int k = x / (panel + gap), px = x % (panel + gap);
      if (px >= panel) {
        raw += {c(0.6), c(0.6), c(0.6)};
        continue;
      }
      double v = std::clamp(fs[size_t(k)][size_t(y / scale) * nx + size_t(px / scale)] / magnitude,
                            -1.0, 1.0);
      if (v >= 0)
        raw += {c(1), c(1 - v), c(1 - v)};
      else
        raw += {c(1 + v), c(1 + v), c(1)};
    }
  }
  // zlib stream of stored deflate blocks (<= 65535 bytes each) + Adler-32.
  std::string z = {0x78, 0x01};
  for (size_t pos = 0; pos < raw.size() || pos == 0;) {
    size_t len = std::min<size_t>(65535, raw.size() - pos);
    bool last = pos + len >= raw.size();
    z.push_back(last ? 1 : 0);
    z.push_back(static_cast<char>(len & 0xff));
    z.push_back(static_cast<char>(len >> 8));
    z.push_back(static_cast<char>(~len & 0xff));
    z.push_back(static_cast<char>((~len >> 8) & 0xff));
    z.append(raw, pos, len);
    pos += len;
    if (last)
      break;
  }
  uint32_t a = 1, b = 0;
  for (unsigned char ch : raw)
    a = (a + ch) % 65521, b = (b + a) % 65521;
  detail::be32(z, (b << 16) | a);
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  detail::be32(ihdr, static_cast<uint32_t>(w));
  detail::be32(ihdr, static_cast<uint32_t>(h));
  ihdr += {8, 2, 0, 0, 0}; // 8-bit RGB
  detail::chunk(png, "IHDR", ihdr);
  detail::chunk(png, "IDAT", z);
  detail::chunk(png, "IEND", "");
  write_atomically(path, png);
}

/// One 2D field as a PNG (see write_png_panels).
inline void write_png_field(const std::string& path, const std::vector<double>& f, int nx, int ny,
                            int scale = 4, double magnitude = 0) {
  write_png_panels(path, {f}, nx, ny, scale, magnitude);
}

} // namespace dpgen_examples
