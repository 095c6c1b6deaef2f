#pragma once

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// A figure described, not scripted: its panels, each panel's axes (label and unit), the data file
// it reads and the series it draws. tools/plot/gnuplot.hpp turns it into a gnuplot script in the
// house style; no other file writes gnuplot (docs/ARCHITECTURE.md, "Plots").
namespace mrd::tools::plot {

// The colours the tools share, so that a model, a bound or the data looks alike in every figure.
namespace colour {
inline constexpr const char* kBlue = "#1f77b4";
inline constexpr const char* kLightBlue = "#9ecae1";
inline constexpr const char* kRed = "#d62728";
inline constexpr const char* kGreen = "#2ca02c";
inline constexpr const char* kOrange = "#ff7f0e";
inline constexpr const char* kPurple = "#9467bd";
inline constexpr const char* kBrown = "#8c564b";
inline constexpr const char* kGrey = "#888888";
inline constexpr const char* kDarkGrey = "#555555";
}  // namespace colour

// A coordinate: a column of the data file (from 1), less another column, times a factor, and
// left out (a gap in the line) where a third column lies outside [from, to].
struct Column {
  int index = 1;
  int subtracted = 0;  // 0: none
  double factor = 1.0;
  int gate = 0;        // 0: none
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();

  [[nodiscard]] Column minus(int other) const {
    Column c = *this;
    c.subtracted = other;
    return c;
  }
  // 1e-3 draws a force in N as kN (say so in the axis' unit).
  [[nodiscard]] Column times(double scale) const {
    Column c = *this;
    c.factor = scale;
    return c;
  }
  [[nodiscard]] Column where(int gate_column, double lowest,
                             double highest = std::numeric_limits<double>::infinity()) const {
    Column c = *this;
    c.gate = gate_column;
    c.from = lowest;
    c.to = highest;
    return c;
  }
};
[[nodiscard]] inline Column column(int index) { return Column{.index = index}; }

enum class Shape { lines, points, rings, dots, steps, impulses };

struct Style {
  Shape shape = Shape::lines;
  std::string colour;  // "#rrggbb"; "" takes gnuplot's next
  double width = 1.0;  // lines, steps, impulses
  double size = 0.2;   // points, rings
  bool dashed = false;
};
[[nodiscard]] inline Style lines(std::string rgb = "", double width = 1.0) {
  return {Shape::lines, std::move(rgb), width};
}
[[nodiscard]] inline Style dashed(std::string rgb) { return {Shape::lines, std::move(rgb), 1.0, 0.2, true}; }
[[nodiscard]] inline Style points(std::string rgb = "", double size = 0.2) {
  return {Shape::points, std::move(rgb), 1.0, size};
}
// Open circles, larger than the points they ring: samples singled out (set aside by screening).
[[nodiscard]] inline Style rings(std::string rgb, double size = 0.5) {
  return {Shape::rings, std::move(rgb), 1.0, size};
}
[[nodiscard]] inline Style dots(std::string rgb) { return {Shape::dots, std::move(rgb)}; }
[[nodiscard]] inline Style steps(std::string rgb = "", double width = 1.0) {
  return {Shape::steps, std::move(rgb), width};
}
[[nodiscard]] inline Style impulses(std::string rgb, double width = 2.0) {
  return {Shape::impulses, std::move(rgb), width};
}

// Drawing order, back to front whatever the order given: the data over the models that try to
// follow it, and notes on the data (samples set aside) over the data.
enum class Layer { model, measured, note };

struct Series {
  std::string title;  // in the key; "" for none
  Column x, y;
  Style style;
  Layer layer = Layer::model;
};

struct DataFile {
  std::string path;  // as gnuplot finds it from where it runs
  bool csv = false;  // the tools' CSV (commas, a column line first); else whitespace, '#' comments
};

struct Range {
  double from = 0.0, to = 0.0;
};

struct Axis {
  std::string label;
  std::string unit;            // drawn as "label [unit]"; "" for a count
  std::optional<Range> range;  // fixed only when asked; autoscaled with headroom otherwise
  bool log = false;
};

// A dotted vertical line across the panel (where the next run begins), its label at the top.
struct Marker {
  double x = 0.0;
  std::string label;  // "" for none
  bool line = true;   // false: the label alone (the first run's name at the left edge)
};

struct Panel {
  std::string title;  // "" for none; a one-panel figure shows the figure's
  Axis x, y;
  DataFile data;
  std::vector<Series> series;
  std::vector<Marker> markers;
};

struct Figure {
  std::string output;   // NAME.svg draws vectors, any other name a PNG
  std::string title;    // over all the panels
  int width = 900, height = 650;
  int columns = 1;      // panels side by side; as many rows as they need
  std::vector<Panel> panels;
  std::string comment;  // lines at the script's top: what it draws, how to redraw it
};

}  // namespace mrd::tools::plot
