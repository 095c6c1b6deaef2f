#pragma once

#include <string>
#include <vector>

#include "tools/plot/figure.hpp"
#include "tools/report/time_chart.hpp"

// One self-contained report.html in a directory: headings, text, tables, zoomable time charts
// (uPlot, inlined once) and plots drawn by gnuplot and inlined (SVG, or PNG where a plot has more
// points than a vector file should carry). Each plot's data (.dat) and script (.gp) stay beside
// the HTML: `cd DIR && gnuplot NAME.gp` redraws it after restyling.
namespace mrd::tools {

// One figure of a table, with the JSON path it stands for (dot-separated; "" for none): the cell
// carries data-key and the full-precision data-value, the text shows six significant digits.
struct ReportFigure {
  std::string label;
  std::string key;
  double value = 0.0;
  std::string unit;
};

// Where a report came from: the tool and its version, how it was called, the files it read
// (the report adds their SHA-256), the seed when the tool draws random numbers.
struct Provenance {
  std::string tool;
  std::string command_line;
  std::vector<std::string> inputs;
  std::string seed;  // "" when the tool draws none
};
[[nodiscard]] Provenance provenance_of(const std::string& tool, int argc, const char* const* argv,
                                       std::vector<std::string> inputs, std::string seed = "");

class HtmlReport {
 public:
  HtmlReport(std::string title, std::string directory);

  void heading(const std::string& text);
  void paragraph(const std::string& text);
  void figures(const std::string& caption, const std::vector<ReportFigure>& rows);
  // Fitted parameters with their standard deviations; the cells carry the JSON paths `key` and
  // `sd_key` (dot-separated, array indices as numbers; "" for a figure the JSON lacks).
  struct Parameter {
    std::string label, unit;
    double value = 0.0, standard_deviation = 0.0;
    std::string key, sd_key;
  };
  void parameters(const std::string& caption, const std::vector<Parameter>& rows);
  // The parameters' correlation matrix (as MATLAB's present/getcov): each cell shaded by |r|, the
  // pairs above 0.95 named below it (the run hardly tells them apart). NaN: not determined.
  void correlation_matrix(const std::string& caption, const std::vector<std::string>& names,
                          const std::vector<std::vector<double>>& correlation);
  // Cells are text (escaped here).
  void table(const std::string& caption, const std::vector<std::string>& header,
             const std::vector<std::vector<std::string>>& rows);
  void provenance(const Provenance& p);

  // NAME.dat with the columns side by side (equal lengths; NaN is written as a gap gnuplot
  // skips), thinned to at most max_rows rows for the plots. Returns the file's name in the
  // directory, for the plot bodies. A header line names the columns.
  std::string data(const std::string& name, const std::vector<std::string>& column_names,
                   const std::vector<const std::vector<double>*>& columns, std::size_t max_rows = 20000);
  // A plot of one panel (tools/plot: the house style), reading a data file of data() by the name
  // it returned. Its caption is the HTML's; the panel needs no title. Scatter plots of long runs
  // are drawn as PNG.
  enum class Drawing { vector, raster };
  void plot(const std::string& name, const std::string& caption, plot::Panel panel,
            Drawing drawing = Drawing::vector);
  // An interactive chart against time (drag to zoom; every chart of the report zooms together).
  void time_chart(const TimeChart& chart);

  // Writes the .dat (already written), .gp, .svg and report.html. Returns "" or why not.
  [[nodiscard]] std::string write();

  [[nodiscard]] const std::string& directory() const { return directory_; }
  [[nodiscard]] std::string html_path() const;

 private:
  struct Plot {
    std::string name, caption;
    plot::Panel panel;
    Drawing drawing = Drawing::vector;
  };
  std::string title_, directory_, error_;
  // HTML pieces in order; a plot stands as an empty piece with its index in plot_at_.
  std::vector<std::string> pieces_;
  std::vector<std::pair<std::size_t, Plot>> plots_;
  bool has_charts_ = false;
};

// Text for HTML: & < > " escaped.
[[nodiscard]] std::string html_escape(const std::string& text);

}  // namespace mrd::tools
