// Pictures for the examples: SVG line plots (loss curves, 1D fields against
// targets) with rounded ticks, grid lines and log axes labelled per decade;
// and PNG figures of 2D fields side by side, with panel titles, axes and a
// colour bar (a diverging map, one symmetric scale for all panels). No
// dependencies; files are written atomically (complete or absent).
#pragma once

#include "png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpgen_examples {

struct Series {
  std::string name;
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dashed = false;
};

/// Ticks of a linear axis: multiples of 1, 2 or 5 x 10^k.
struct Ticks {
  double lo, hi, step;       ///< the axis runs from lo to hi
  std::vector<double> value; ///< the ticks in [lo, hi]
};

/// Ticks at round values for data in [lo, hi], at most about `target`
/// intervals between them (the smallest round step that many cover). An end of the
/// axis moves out to the next tick where that adds at most `widen` times the
/// data's span (x from -0.992 to 0.992 gets an axis from -1 to 1); otherwise
/// it stays at the data and has no tick there.
inline Ticks nice_ticks(double lo, double hi, int target = 6, double widen = 0.1) {
  if (!(std::isfinite(lo) && std::isfinite(hi)))
    lo = 0, hi = 1;
  if (hi < lo)
    std::swap(lo, hi);
  if (hi == lo) {
    const double pad = lo == 0 ? 1 : 0.5 * std::abs(lo);
    lo -= pad, hi += pad;
  }
  const double raw = (hi - lo) / std::max(1, target);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (double m : {1.0, 2.0, 5.0})
    if (m * mag >= raw * (1 - 1e-9)) {
      step = m * mag;
      break;
    }
  const double eps = 1e-9 * step;
  const double tlo = std::floor(lo / step + 1e-9) * step, thi = std::ceil(hi / step - 1e-9) * step;
  Ticks t{lo - tlo <= widen * (hi - lo) + eps ? tlo : lo,
          thi - hi <= widen * (hi - lo) + eps ? thi : hi,
          step,
          {}};
  for (double v = std::ceil(t.lo / step - 1e-9) * step; v <= t.hi + eps; v += step)
    t.value.push_back(std::abs(v) < eps ? 0.0 : v);
  return t;
}

/// A tick label with as many decimals as the step needs ("0.25", "-1", "2e-05"
/// for steps below 1e-4 or values of 1e5 and more); never "-0".
inline std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-9 * step)
    v = 0;
  char buf[32];
  if (step < 1e-4 || std::abs(v) >= 1e5) {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  } else {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  return buf;
}

namespace detail {
inline std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s)
    switch (c) {
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '&':
      out += "&amp;";
      break;
    case '\'':
      out += "&apos;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  return out;
}
// A typographic minus for SVG text.
inline std::string svg_minus(std::string s) {
  if (!s.empty() && s[0] == '-')
    s.replace(0, 1, "&#8722;");
  return s;
}
inline std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}
} // namespace detail

/// A line plot: title, axis labels, round ticks with grid lines, a legend.
/// log_y: a logarithmic y axis over whole decades, a label at every decade
/// (10^k; every second one beyond 16 decades...) and minor ticks at 2..9 x 10^k
/// up to 6 decades; values <= 0 are left out there. Non-finite values
/// are left out (the line is interrupted).
inline void write_svg_plot(const std::string& path, const std::string& title,
                           const std::string& xlabel, const std::string& ylabel,
                           const std::vector<Series>& series, bool log_y = false) {
  using detail::fmt;
  using detail::xml_escape;
  const double W = 720, H = 440, L = 78, R = 20, T = 40, B = 56;
  auto ty = [&](double y) { return log_y ? std::log10(y) : y; };
  auto usable = [&](double x, double y) {
    return std::isfinite(x) && std::isfinite(y) && (!log_y || y > 0);
  };
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("write_svg_plot: series '" + s.name + "' has " +
                                  std::to_string(s.x.size()) + " x and " +
                                  std::to_string(s.y.size()) + " y values");
    for (size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], s.y[i])) {
        x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
        y0 = std::min(y0, ty(s.y[i])), y1 = std::max(y1, ty(s.y[i]));
      }
  }
  const Ticks xt = nice_ticks(x0, x1, 7);
  // y: round ticks over the data (padded by 3%), or whole decades.
  Ticks yt;
  int label_every = 1;
  if (log_y) {
    if (!std::isfinite(y0))
      y0 = 0, y1 = 1;
    yt.lo = std::floor(y0), yt.hi = std::max(std::ceil(y1), yt.lo + 1), yt.step = 1;
    for (double e = yt.lo; e <= yt.hi; ++e)
      yt.value.push_back(e);
    label_every = std::max(1, static_cast<int>(std::ceil((yt.hi - yt.lo) / 16)));
  } else {
    const double pad = std::isfinite(y0) ? 0.03 * (y1 - y0) : 0;
    yt = nice_ticks(y0 - pad, y1 + pad, 6);
  }
  const double pw = W - L - R, ph = H - T - B;
  auto px = [&](double x) { return L + (x - xt.lo) / (xt.hi - xt.lo) * pw; };
  auto pyv = [&](double v) { return T + ph - (v - yt.lo) / (yt.hi - yt.lo) * ph; };

  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' viewBox='0 0 " << W << " " << H
    << "' font-family='DejaVu Sans, Helvetica, Arial, sans-serif' font-size='12'>\n"
    << "<rect width='100%' height='100%' fill='white'/>\n"
    << "<clipPath id='plot-area'><rect x='" << L << "' y='" << T << "' width='" << pw
    << "' height='" << ph << "'/></clipPath>\n";
  o << "<text x='" << (L + W - R) / 2 << "' y='24' text-anchor='middle' font-size='15'>"
    << xml_escape(title) << "</text>\n";
  // Grid lines and ticks.
  o << "<g stroke='#e3e3e3' stroke-width='1'>\n";
  for (double v : xt.value)
    o << "<line x1='" << fmt(px(v)) << "' y1='" << T << "' x2='" << fmt(px(v)) << "' y2='" << T + ph
      << "'/>\n";
  for (double v : yt.value)
    o << "<line x1='" << L << "' y1='" << fmt(pyv(v)) << "' x2='" << L + pw << "' y2='"
      << fmt(pyv(v)) << "'/>\n";
  o << "</g>\n";
  const bool minor = log_y && yt.hi - yt.lo <= 6;
  if (minor) {
    o << "<g stroke='#f0f0f0' stroke-width='1'>\n";
    for (double e = yt.lo; e < yt.hi; ++e)
      for (int m = 2; m <= 9; ++m)
        o << "<line x1='" << L << "' y1='" << fmt(pyv(e + std::log10(m))) << "' x2='" << L + pw
          << "' y2='" << fmt(pyv(e + std::log10(m))) << "'/>\n";
    o << "</g>\n";
  }
  o << "<g stroke='black'>\n";
  for (double v : xt.value)
    o << "<line x1='" << fmt(px(v)) << "' y1='" << T + ph << "' x2='" << fmt(px(v)) << "' y2='"
      << T + ph + 5 << "'/>\n";
  for (double v : yt.value)
    o << "<line x1='" << L - 5 << "' y1='" << fmt(pyv(v)) << "' x2='" << L << "' y2='"
      << fmt(pyv(v)) << "'/>\n";
  if (minor)
    for (double e = yt.lo; e < yt.hi; ++e)
      for (int m = 2; m <= 9; ++m)
        o << "<line x1='" << L - 3 << "' y1='" << fmt(pyv(e + std::log10(m))) << "' x2='" << L
          << "' y2='" << fmt(pyv(e + std::log10(m))) << "'/>\n";
  o << "</g>\n";
  for (double v : xt.value)
    o << "<text x='" << fmt(px(v)) << "' y='" << T + ph + 19 << "' text-anchor='middle'>"
      << detail::svg_minus(tick_label(v, xt.step)) << "</text>\n";
  for (size_t k = 0; k < yt.value.size(); ++k) {
    const double v = yt.value[k];
    if (log_y) {
      if (static_cast<int>(v - yt.lo) % label_every)
        continue;
      const int e = static_cast<int>(v);
      o << "<text x='" << L - 8 << "' y='" << fmt(pyv(v) + 4)
        << "' text-anchor='end'>10<tspan dy='-6' font-size='9'>" << (e < 0 ? "&#8722;" : "")
        << std::abs(e) << "</tspan></text>\n";
    } else {
      o << "<text x='" << L - 8 << "' y='" << fmt(pyv(v) + 4) << "' text-anchor='end'>"
        << detail::svg_minus(tick_label(v, yt.step)) << "</text>\n";
    }
  }
  o << "<text x='" << L + pw / 2 << "' y='" << H - 12 << "' text-anchor='middle'>"
    << xml_escape(xlabel) << "</text>\n";
  o << "<text x='16' y='" << T + ph / 2 << "' text-anchor='middle' transform='rotate(-90 16 "
    << T + ph / 2 << ")'>" << xml_escape(ylabel) << "</text>\n";
  // The data, clipped to the plot area; a non-usable value breaks the line.
  o << "<g clip-path='url(#plot-area)' fill='none' stroke-width='1.8' stroke-linejoin='round'>\n";
  for (const auto& s : series) {
    std::string points;
    auto flush = [&] {
      if (!points.empty())
        o << "<polyline stroke='" << s.color << "'" << (s.dashed ? " stroke-dasharray='6,4'" : "")
          << " points='" << points << "'/>\n";
      points.clear();
    };
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!usable(s.x[i], s.y[i])) {
        flush();
        continue;
      }
      points += fmt(px(s.x[i])) + "," + fmt(pyv(ty(s.y[i]))) + " ";
    }
    flush();
  }
  o << "</g>\n";
  o << "<rect x='" << L << "' y='" << T << "' width='" << pw << "' height='" << ph
    << "' fill='none' stroke='black'/>\n";
  // The legend on a white box, in the corner that hides the fewest data
  // points (top right, top left, bottom right, bottom left on a tie).
  if (!series.empty()) {
    size_t longest = 0;
    for (const auto& s : series)
      longest = std::max(longest, s.name.size());
    const double lw = 42 + 7.0 * static_cast<double>(longest), lh = 8 + 18.0 * series.size();
    double lx = 0, ly = 0;
    size_t fewest = std::numeric_limits<size_t>::max();
    for (const auto& [cx, cy] :
         {std::pair{L + pw - lw - 8, T + 8}, std::pair{L + 8, T + 8},
          std::pair{L + pw - lw - 8, T + ph - lh - 8}, std::pair{L + 8, T + ph - lh - 8}}) {
      size_t hidden = 0;
      for (const auto& s : series)
        for (size_t i = 0; i < s.x.size(); ++i)
          if (usable(s.x[i], s.y[i])) {
            const double x = px(s.x[i]), y = pyv(ty(s.y[i]));
            hidden += x >= cx - 4 && x <= cx + lw + 4 && y >= cy - 4 && y <= cy + lh + 4;
          }
      if (hidden < fewest)
        fewest = hidden, lx = cx, ly = cy;
    }
    o << "<rect x='" << fmt(lx) << "' y='" << ly << "' width='" << fmt(lw) << "' height='" << lh
      << "' fill='white' fill-opacity='0.9' stroke='#bbbbbb'/>\n";
    for (size_t k = 0; k < series.size(); ++k) {
      const auto& s = series[k];
      const double y = ly + 13 + 18.0 * static_cast<double>(k);
      o << "<line x1='" << fmt(lx + 8) << "' y1='" << y << "' x2='" << fmt(lx + 32) << "' y2='" << y
        << "' stroke='" << s.color << "' stroke-width='2'"
        << (s.dashed ? " stroke-dasharray='6,4'" : "") << "/><text x='" << fmt(lx + 38) << "' y='"
        << y + 4 << "'>" << xml_escape(s.name) << "</text>\n";
    }
  }
  o << "</svg>\n";
  write_atomically(path, o.str());
}

/// How write_png_fields lays out its panels.
struct FieldFigure {
  std::string title;                     ///< above the panels
  std::vector<std::string> panel_titles; ///< one per field, above each panel
  std::string xlabel = "x", ylabel = "y";
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1; ///< the domain the cells cover
  std::vector<double> x_lines; ///< dashed vertical lines at these x (every panel)
  std::string value_label;     ///< next to the colour bar
  double magnitude =
      0; ///< colours span [-magnitude, magnitude] (rounded up to a tick); 0: max |value|
  int cell_pixels = 4; ///< pixels per cell
};

/// The diverging colour map (ColorBrewer RdBu, reversed): t in [-1, 1],
/// blue - white - red.
inline Rgb diverging_color(double t) {
  static const Rgb stops[9] = {{33, 102, 172},  {67, 147, 195},  {146, 197, 222},
                               {209, 229, 240}, {247, 247, 247}, {253, 219, 199},
                               {244, 165, 130}, {214, 96, 77},   {178, 24, 43}};
  if (!std::isfinite(t))
    return {128, 128, 128};
  const double s = (std::clamp(t, -1.0, 1.0) + 1) * 4; // 0 .. 8
  const int k = std::min(7, static_cast<int>(s));
  const double f = s - k;
  auto mix = [&](uint8_t a, uint8_t b) { return static_cast<uint8_t>(a + (b - a) * f + 0.5); };
  return {mix(stops[k].r, stops[k + 1].r), mix(stops[k].g, stops[k + 1].g),
          mix(stops[k].b, stops[k + 1].b)};
}

/// 2D fields (row-major, nx by ny, row 0 at the bottom) side by side in one
/// PNG: a title, a title over each panel, x ticks under every panel, y ticks
/// left of the first, and a colour bar with its scale on the right (with a
/// triangle at an end where values go beyond it). NaN cells are grey.
inline void write_png_fields(const std::string& path, const std::vector<std::vector<double>>& fs,
                             int nx, int ny, const FieldFigure& fig) {
  if (fs.empty() || nx < 1 || ny < 1)
    throw std::invalid_argument("write_png_fields: no fields or an empty grid (" +
                                std::to_string(nx) + "x" + std::to_string(ny) + ")");
  for (const auto& f : fs)
    if (f.size() != size_t(nx) * size_t(ny))
      throw std::invalid_argument("write_png_fields: field has " + std::to_string(f.size()) +
                                  " values, expected " + std::to_string(nx) + "x" +
                                  std::to_string(ny));
  if (!(fig.x_max > fig.x_min && fig.y_max > fig.y_min))
    throw std::invalid_argument("write_png_fields: empty domain");
  double largest = 0;
  for (const auto& f : fs)
    for (double v : f)
      if (std::isfinite(v))
        largest = std::max(largest, std::abs(v));
  double m = fig.magnitude > 0 ? fig.magnitude : largest;
  if (!(m > 0))
    m = 1;
  // The colour bar's scale: 5 to 9 ticks, its ends on ticks, widened the least.
  Ticks ct = nice_ticks(-m, m, 5, 1e300);
  for (int target = 6; target <= 9; ++target) {
    Ticks t = nice_ticks(-m, m, target, 1e300);
    if (t.hi < ct.hi * (1 - 1e-9))
      ct = std::move(t);
  }
  m = std::max(-ct.lo, ct.hi);
  bool above = false, below = false;
  for (const auto& f : fs)
    for (double v : f)
      above = above || v > m, below = below || v < -m;

  const int S = 2; // text scale
  // Text: line height th, digits centred on a tick with their cap height ch.
  const int th = Canvas::kGlyphH * S, ch = Canvas::kCapH * S, pad = 8, tick = 5;
  const int cp = std::max(1, fig.cell_pixels), pw = nx * cp, ph = ny * cp;
  const int n = static_cast<int>(fs.size());
  const Ticks xt = nice_ticks(fig.x_min, fig.x_max, std::max(2, pw / 60));
  const Ticks yt = nice_ticks(fig.y_min, fig.y_max, std::max(2, ph / 50));
  int xlab_w = 0, ylab_w = 0, clab_w = 0;
  for (double v : xt.value)
    xlab_w = std::max(xlab_w, Canvas::text_width(tick_label(v, xt.step), S));
  for (double v : yt.value)
    if (v >= fig.y_min - 1e-9 * yt.step && v <= fig.y_max + 1e-9 * yt.step)
      ylab_w = std::max(ylab_w, Canvas::text_width(tick_label(v, yt.step), S));
  for (double v : ct.value)
    clab_w = std::max(clab_w, Canvas::text_width(tick_label(v, ct.step), S));
  const int gap = std::max(28, xlab_w + 12), bar_gap = 24, bar_w = 16, tri = 10;
  const bool panel_titles = !fig.panel_titles.empty();
  // Labels of up to 3 characters stay horizontal; longer ones read upwards.
  auto label_w = [&](const std::string& l) {
    return l.empty() ? 0 : (l.size() <= 3 ? Canvas::text_width(l, S) : th) + 8;
  };
  const int left = pad + label_w(fig.ylabel) + ylab_w + 4 + tick;
  const int top = pad + (fig.title.empty() ? 0 : th + 10) + (panel_titles ? th + 8 : 0) + tri;
  const int panels_w = n * pw + (n - 1) * gap;
  const int width =
      left + panels_w + bar_gap + bar_w + tick + 4 + clab_w + 2 + label_w(fig.value_label) + pad;
  const int height = top + ph + tick + 4 + th + (fig.xlabel.empty() ? 0 : 8 + th) + pad;
  const int title_w = Canvas::text_width(fig.title, S) + 1; // bold: one pixel wider
  Canvas c(std::max(width, title_w + 2 * pad), height);
  const Rgb black{}, grey{90, 90, 90};
  auto side_label = [&](int x, int y, const std::string& l) {
    if (l.size() <= 3)
      c.text(x, y - ch / 2, l, S);
    else
      c.text_up(x, y, l, S);
  };

  if (!fig.title.empty())
    c.text(std::clamp(left + panels_w / 2, pad + title_w / 2, c.width() - pad - title_w / 2), pad,
           fig.title, S, 0, black, true);
  auto in_domain = [](double v, double lo, double hi, double step) {
    return v >= lo - 1e-9 * step && v <= hi + 1e-9 * step;
  };
  for (int k = 0; k < n; ++k) {
    const int x0 = left + k * (pw + gap);
    const auto& f = fs[size_t(k)];
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        c.fill(x0 + i * cp, top + (ny - 1 - j) * cp, cp, cp,
               diverging_color(f[size_t(j) * size_t(nx) + size_t(i)] / m));
    for (double xv : fig.x_lines)
      if (xv > fig.x_min && xv < fig.x_max)
        c.dashed_vline(
            x0 + static_cast<int>(std::lround((xv - fig.x_min) / (fig.x_max - fig.x_min) * pw)),
            top, top + ph, grey);
    c.frame(x0, top, pw, ph, black);
    if (panel_titles && size_t(k) < fig.panel_titles.size())
      c.text(x0 + pw / 2, top - tri - 8 - th, fig.panel_titles[size_t(k)], S, 0);
    for (double v : xt.value) {
      if (!in_domain(v, fig.x_min, fig.x_max, xt.step))
        continue;
      const int x =
          x0 + static_cast<int>(std::lround((v - fig.x_min) / (fig.x_max - fig.x_min) * pw));
      const int xx = std::min(x, x0 + pw); // the right edge tick on the frame
      c.fill(xx, top + ph + 1, 1, tick, black);
      c.text(xx, top + ph + 1 + tick + 3, tick_label(v, xt.step), S, 0);
    }
    if (!fig.xlabel.empty())
      c.text(x0 + pw / 2, top + ph + 1 + tick + 3 + th + 8, fig.xlabel, S, 0);
  }
  for (double v : yt.value) {
    if (!in_domain(v, fig.y_min, fig.y_max, yt.step))
      continue;
    const int y =
        top + ph - static_cast<int>(std::lround((v - fig.y_min) / (fig.y_max - fig.y_min) * ph));
    const int yy = std::min(y, top + ph);
    c.fill(left - 1 - tick, yy, tick, 1, black);
    c.text(left - 1 - tick - 4, yy - ch / 2, tick_label(v, yt.step), S, 1);
  }
  side_label(pad, top + ph / 2, fig.ylabel);

  // The colour bar: +m at the top, -m at the bottom.
  const int bx = left + panels_w + bar_gap;
  for (int r = 0; r < ph; ++r)
    c.fill(bx, top + r, bar_w, 1, diverging_color(1 - 2 * (r + 0.5) / ph));
  c.frame(bx, top, bar_w, ph, black);
  for (int t = 0; t < tri; ++t) { // triangles: values beyond the scale
    const int half = (bar_w * (t + 1)) / (2 * tri);
    if (above)
      c.fill(bx + bar_w / 2 - half, top - tri + t - 1, 2 * half, 1, diverging_color(1));
    if (below)
      c.fill(bx + bar_w / 2 - half, top + ph + tri - t, 2 * half, 1, diverging_color(-1));
  }
  for (double v : ct.value) {
    const int y = top + static_cast<int>(std::lround((m - v) / (2 * m) * ph));
    const int yy = std::min(y, top + ph);
    c.fill(bx + bar_w + 1, yy, tick, 1, black);
    c.text(bx + bar_w + 1 + tick + 4, yy - ch / 2, tick_label(v, ct.step), S, -1);
  }
  side_label(bx + bar_w + 1 + tick + 4 + clab_w + 10, top + ph / 2, fig.value_label);
  c.write_png(path);
}

} // namespace dpgen_examples
