#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace hullcook::bench {
namespace {

std::string svg_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

std::string number_label(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

// Tick values for an axis over [low, high]: decades (with 2 and 5 when few decades) on a log
// axis, 1-2-5 steps on a linear one.
std::vector<double> axis_ticks(double low, double high, bool log_axis) {
  std::vector<double> ticks;
  if (log_axis) {
    int first = static_cast<int>(std::floor(std::log10(low) + 1e-9));
    int last = static_cast<int>(std::ceil(std::log10(high) - 1e-9));
    bool fine = last - first <= 2;
    for (int e = first; e <= last; ++e)
      for (double step : {1.0, 2.0, 5.0}) {
        if (step != 1.0 && !fine) continue;
        double value = step * std::pow(10.0, e);
        if (value >= low * 0.999 && value <= high * 1.001) ticks.push_back(value);
      }
    return ticks;
  }
  double raw = (high - low) / 5;
  double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude * (raw / magnitude <= 1   ? 1
                             : raw / magnitude <= 2 ? 2
                             : raw / magnitude <= 5 ? 5
                                                    : 10);
  for (double value = std::ceil(low / step - 1e-9) * step; value <= high + step * 1e-6;
       value += step)
    ticks.push_back(std::abs(value) < step * 1e-9 ? 0.0 : value);
  return ticks;
}

}  // namespace

std::string line_plot_svg(const std::string& title, const std::string& x_label,
                          const std::string& y_label, const std::vector<double>& xs,
                          const std::vector<Series>& series, bool log_y) {
  const double width = 600, height = 340, left = 70, right = 150, top = 34, bottom = 50;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  double x_low = *std::min_element(xs.begin(), xs.end()),
         x_high = *std::max_element(xs.begin(), xs.end());
  x_low = std::pow(10.0, std::floor(std::log10(x_low) + 1e-9));
  x_high = std::pow(10.0, std::ceil(std::log10(x_high) - 1e-9));
  double y_low = INFINITY, y_high = -INFINITY;
  for (const Series& s : series)
    for (double y : s.ys) {
      if (!std::isfinite(y) || (log_y && y <= 0)) continue;
      y_low = std::min(y_low, y);
      y_high = std::max(y_high, y);
    }
  if (!std::isfinite(y_low)) y_low = y_high = 1;
  if (log_y) {
    y_low = std::pow(10.0, std::floor(std::log10(y_low) + 1e-9));
    y_high = std::pow(10.0, std::ceil(std::log10(y_high) - 1e-9));
    if (y_high <= y_low) y_high = y_low * 10;
  } else {
    // 1-2-5 steps; the range ends on steps so that e.g. convexity tops out at exactly 1.
    std::vector<double> ticks = axis_ticks(y_low, std::max(y_high, y_low + 1e-3), false);
    double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1e-3;
    y_low = std::floor(y_low / step + 1e-9) * step;
    y_high = std::max(std::ceil(y_high / step - 1e-9) * step, y_low + step);
  }
  auto to_x = [&](double x) {
    return left +
           plot_w * (std::log10(x) - std::log10(x_low)) / (std::log10(x_high) - std::log10(x_low));
  };
  auto to_y = [&](double y) {
    double t = log_y
                   ? (std::log10(y) - std::log10(y_low)) / (std::log10(y_high) - std::log10(y_low))
                   : (y - y_low) / (y_high - y_low);
    return top + plot_h * (1 - t);
  };
  std::ostringstream svg;
  svg << std::setprecision(5);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << left + plot_w / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"13\">"
      << svg_escape(title) << "</text>\n";
  // Grid and ticks.
  for (double x : axis_ticks(x_low, x_high, true)) {
    double px = to_x(x);
    svg << "<line x1=\"" << px << "\" y1=\"" << top << "\" x2=\"" << px << "\" y2=\""
        << top + plot_h << "\" stroke=\"#e4e4e4\"/>\n";
    svg << "<text x=\"" << px << "\" y=\"" << top + plot_h + 15 << "\" text-anchor=\"middle\">"
        << number_label(x) << "</text>\n";
  }
  for (double y : axis_ticks(y_low, y_high, log_y)) {
    double py = to_y(y);
    svg << "<line x1=\"" << left << "\" y1=\"" << py << "\" x2=\"" << left + plot_w << "\" y2=\""
        << py << "\" stroke=\"#e4e4e4\"/>\n";
    svg << "<text x=\"" << left - 5 << "\" y=\"" << py + 4 << "\" text-anchor=\"end\">"
        << number_label(y) << "</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plot_w << "\" height=\""
      << plot_h << "\" fill=\"none\" stroke=\"black\"/>\n";
  svg << "<text x=\"" << left + plot_w / 2 << "\" y=\"" << height - 12
      << "\" text-anchor=\"middle\">" << svg_escape(x_label) << "</text>\n";
  svg << "<text transform=\"translate(16 " << top + plot_h / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << svg_escape(y_label) << "</text>\n";
  // Lines, markers and legend.
  for (std::size_t s = 0; s < series.size(); ++s) {
    const Series& line = series[s];
    std::ostringstream points;
    points << std::setprecision(5);
    std::vector<std::pair<double, double>> marks;
    for (std::size_t i = 0; i < xs.size() && i < line.ys.size(); ++i) {
      double y = line.ys[i];
      if (!std::isfinite(y) || (log_y && y <= 0)) continue;
      points << to_x(xs[i]) << ',' << to_y(y) << ' ';
      marks.emplace_back(to_x(xs[i]), to_y(y));
    }
    svg << "<polyline fill=\"none\" stroke=\"" << line.color << "\" stroke-width=\"1.8\"";
    if (!line.dash.empty()) svg << " stroke-dasharray=\"" << line.dash << '"';
    svg << " points=\"" << points.str() << "\"/>\n";
    for (auto [px, py] : marks)
      svg << "<circle cx=\"" << px << "\" cy=\"" << py << "\" r=\"2.5\" fill=\"" << line.color
          << "\"/>\n";
    double ly = top + 14 + 18 * static_cast<double>(s);
    svg << "<line x1=\"" << left + plot_w + 12 << "\" y1=\"" << ly << "\" x2=\""
        << left + plot_w + 40 << "\" y2=\"" << ly << "\" stroke=\"" << line.color
        << "\" stroke-width=\"1.8\"";
    if (!line.dash.empty()) svg << " stroke-dasharray=\"" << line.dash << '"';
    svg << "/>\n<text x=\"" << left + plot_w + 46 << "\" y=\"" << ly + 4 << "\">"
        << svg_escape(line.name) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace hullcook::bench
