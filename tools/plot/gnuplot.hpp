#pragma once

#include <string>
#include <vector>

#include "tools/plot/figure.hpp"

// The one place that writes gnuplot. The house style, applied to every figure: text taken
// literally (noenhanced: `preyield_hysteresis` is not typeset with a subscript), the key below
// the panel and outside the data, autoscaled axes with headroom so that no trace lies on the
// frame, a grid, white background, the measured trace drawn over the models.
namespace mrd::tools::plot {

// The script that draws `figure` into figure.output.
[[nodiscard]] std::string gnuplot_script(const Figure& figure);

// Draws the figures in one gnuplot run. Returns "" or why not (gnuplot missing: the caller notes
// it and carries on without the plots).
[[nodiscard]] std::string draw(const std::vector<Figure>& figures);

// A data file gnuplot reads: a '#' line naming the columns, then the columns side by side, thinned
// to at most max_rows rows. A column shorter than the longest, or a value that is not finite, is
// written NaN: gnuplot lifts the pen there (between loops) and draws nothing past a short column's
// end. Returns "" or why not.
[[nodiscard]] std::string write_columns(const std::string& path, const std::vector<std::string>& names,
                                        const std::vector<const std::vector<double>*>& columns,
                                        std::size_t max_rows = static_cast<std::size_t>(-1));

// Runs the scripts NAME.gp written into `directory` (their files named relative to it), as a
// report keeps them beside its HTML. Returns "" or why not.
[[nodiscard]] std::string draw_scripts(const std::string& directory, const std::vector<std::string>& names);

}  // namespace mrd::tools::plot
