// A small SVG line plot for the benchmarks' figures in docs/plots: a log x axis, a linear or log
// y axis, one polyline with markers per series, and a legend.
#pragma once

#include <string>
#include <vector>

namespace hullcook::bench {

struct Series {
  std::string name;
  std::string color;
  std::string dash;  // SVG stroke-dasharray, empty for solid
  std::vector<double> ys;
};

// The plot's SVG text: series[s].ys[i] is drawn at xs[i] (xs > 0); values that are not finite,
// or not positive on a log y axis, are left out.
std::string line_plot_svg(const std::string& title, const std::string& x_label,
                          const std::string& y_label, const std::vector<double>& xs,
                          const std::vector<Series>& series, bool log_y);

}  // namespace hullcook::bench
