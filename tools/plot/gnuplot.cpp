#include "tools/plot/gnuplot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "tools/text_format.hpp"

namespace mrd::tools::plot {

namespace {

// Before each further figure of one gnuplot run: `reset` leaves a CSV's column line setting on.
constexpr const char* kBetweenFigures = "reset\nset datafile nocolumnheaders\n";

std::string run_gnuplot(const std::string& script) {
  FILE* pipe = popen("gnuplot 2>&1 >/dev/null", "w");
  if (pipe == nullptr) return "cannot start gnuplot";
  const bool written = std::fwrite(script.data(), 1, script.size(), pipe) == script.size();
  const int status = pclose(pipe);
  if (!written || status != 0) return "gnuplot failed (is gnuplot installed? apt-get install gnuplot-nox)";
  return {};
}

// A gnuplot string: single quotes take everything literally but a quote, which is doubled.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string number(double value) { return format("%.9g", value); }

std::string label_of(const Axis& axis) { return axis.unit.empty() ? axis.label : axis.label + " [" + axis.unit + "]"; }

// A column as gnuplot's `using` reads it: its number, or an expression of $N where there is arithmetic.
std::string coordinate(const Column& c) {
  if (c.subtracted == 0 && c.factor == 1.0 && c.gate == 0) return std::to_string(c.index);
  std::string value = c.subtracted == 0 ? format("$%d", c.index) : format("$%d-$%d", c.index, c.subtracted);
  if (c.factor != 1.0) value = (c.subtracted == 0 ? value : "(" + value + ")") + "*" + number(c.factor);
  std::string test;
  if (c.gate != 0 && std::isfinite(c.from)) test = format("$%d>=", c.gate) + number(c.from);
  if (c.gate != 0 && std::isfinite(c.to)) test += format(test.empty() ? "$%d<=" : "&&$%d<=", c.gate) + number(c.to);
  return test.empty() ? "(" + value + ")" : "(" + test + "?" + value + ":1/0)";
}

std::string with(const Style& s) {
  std::string out;
  switch (s.shape) {
    case Shape::lines: out = "lines lw " + number(s.width) + (s.dashed ? " dt 2" : ""); break;
    case Shape::points: out = "points pt 7 ps " + number(s.size); break;
    case Shape::rings: out = "points pt 6 ps " + number(s.size); break;
    case Shape::dots: out = "dots"; break;
    case Shape::steps: out = "steps lw " + number(s.width); break;
    case Shape::impulses: out = "impulses lw " + number(s.width); break;
  }
  return s.colour.empty() ? out : out + " lc rgb " + quoted(s.colour);
}

// The series back to front (models, the measured, notes), one a line.
std::string plot_command(const Panel& panel) {
  std::vector<const Series*> order;
  for (const Series& s : panel.series) order.push_back(&s);
  std::stable_sort(order.begin(), order.end(), [](const Series* a, const Series* b) { return a->layer < b->layer; });
  std::string out = "plot ";
  std::string keys;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Series& s = *order[i];
    // A dot is one pixel in the key too: a titled series of dots gets its key from an empty
    // series of points in its colour.
    const bool dot_key = s.style.shape == Shape::dots && !s.title.empty() && !s.style.colour.empty();
    out += (i == 0 ? quoted(panel.data.path) : ", \\\n     ''") + " using " + coordinate(s.x) + ":" + coordinate(s.y) +
           " with " + with(s.style) + (s.title.empty() || dot_key ? " notitle" : " title " + quoted(s.title));
    if (dot_key) keys += ", \\\n     NaN with points pt 7 ps 0.8 lc rgb " + quoted(s.style.colour) + " title " + quoted(s.title);
  }
  return out + keys + "\n";
}

std::string axis_settings(const Axis& axis, const char* name) {
  std::string out = format("set %slabel ", name) + quoted(label_of(axis)) + "\n";
  if (axis.range) out += format("set %srange [", name) + number(axis.range->from) + ":" + number(axis.range->to) + "]\n";
  // A log axis' ticks as plain numbers: gnuplot's default pads them to the smallest decade's
  // digits (0.0100000 beside 0.0000001).
  if (axis.log) out += format("set logscale %s\nset format %s '%%g'\n", name, name);
  return out;
}

std::string markers(const Panel& panel) {
  std::string out;
  for (const Marker& m : panel.markers) {
    if (m.line)
      out += "set arrow from " + number(m.x) + ", graph 0 to " + number(m.x) + ", graph 1 nohead dt 3 lc rgb " +
             quoted(colour::kGrey) + "\n";
    if (!m.label.empty()) out += "set label " + quoted(m.label) + " at " + number(m.x) + ", graph 0.97 left front font ',8'\n";
  }
  return out;
}

}  // namespace

std::string gnuplot_script(const Figure& figure) {
  std::string out;
  std::size_t from = 0;
  while (from < figure.comment.size()) {
    const std::size_t end = std::min(figure.comment.find('\n', from), figure.comment.size());
    out += "# " + figure.comment.substr(from, end - from) + "\n";
    from = end + 1;
  }
  const bool svg = figure.output.ends_with(".svg");
  out += format("set terminal %s noenhanced size %d,%d font 'Helvetica,%d' background '#ffffff'\n",
                svg ? "svg" : "pngcairo", figure.width, figure.height, svg ? 12 : 10);
  out += "set output " + quoted(figure.output) + "\n";
  // Headroom above and below the data: autoscaling alone ends the axis at the tick nearest the
  // extreme, where a trace at its peak (B at 1.4 T) would run along the frame and vanish.
  // The key's extra line of height keeps it clear of the x label (in a grid of panels it sat on it).
  out += "set grid\nset key below horizontal height 1\nset offsets 0, 0, graph 0.05, graph 0.05\n";
  const bool several = figure.panels.size() > 1;
  if (several) {
    const int columns = std::max(1, figure.columns);
    const int rows = (static_cast<int>(figure.panels.size()) + columns - 1) / columns;
    out += format("set multiplot layout %d,%d title ", rows, columns) + quoted(figure.title) + "\n";
  }
  bool csv = false;  // gnuplot's default: whitespace, no column line
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const Panel& panel = figure.panels[i];
    // Nothing a panel set carries over into the next.
    if (i > 0) out += "unset arrow\nunset label\nunset logscale\nset autoscale\nset format\n";
    const std::string& title = several || figure.title.empty() ? panel.title : figure.title;
    if (!title.empty()) {
      out += "set title " + quoted(title) + "\n";
    } else if (i > 0) {
      out += "unset title\n";
    }
    if (panel.data.csv != csv) {
      csv = panel.data.csv;
      out += csv ? "set datafile separator ','\nset datafile columnheaders\n"
                 : "set datafile separator whitespace\nset datafile nocolumnheaders\n";
    }
    out += axis_settings(panel.x, "x") + axis_settings(panel.y, "y") + markers(panel) + plot_command(panel);
  }
  if (several) out += "unset multiplot\n";
  return out + "unset output\n";
}

std::string draw(const std::vector<Figure>& figures) {
  std::string script;
  for (const Figure& f : figures) script += (script.empty() ? "" : kBetweenFigures) + gnuplot_script(f);
  return run_gnuplot(script);
}

std::string write_columns(const std::string& path, const std::vector<std::string>& names,
                          const std::vector<const std::vector<double>*>& columns, std::size_t max_rows) {
  std::size_t rows = 0;
  for (const auto* c : columns) rows = std::max(rows, c->size());
  const std::size_t most = std::max<std::size_t>(1, max_rows);
  const std::size_t stride = rows <= most ? 1 : (rows + most - 1) / most;
  std::ofstream out(path);
  out << "#";
  for (const auto& name : names) out << ' ' << name;
  out << '\n';
  char cell[32];
  for (std::size_t i = 0; i < rows; i += stride) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double v = i < columns[c]->size() ? (*columns[c])[i] : NAN;
      std::snprintf(cell, sizeof cell, std::isfinite(v) ? "%.9g" : "NaN", v);
      out << (c ? " " : "") << cell;
    }
    out << '\n';
  }
  return out ? "" : "cannot write " + path;
}

std::string draw_scripts(const std::string& directory, const std::vector<std::string>& names) {
  std::string script = "cd " + quoted(std::filesystem::absolute(directory).string()) + "\n";
  for (const std::string& name : names) script += kBetweenFigures + std::string("load ") + quoted(name + ".gp") + "\n";
  return run_gnuplot(script);
}

}  // namespace mrd::tools::plot
