// The plotting module (tools/plot): a figure rendered to a gnuplot script carries the house
// style, and gnuplot draws it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tools/plot/gnuplot.hpp"

namespace plot_script_test {

namespace plot = mrd::tools::plot;

// Force against displacement as the tools draw it: two models and the measured trace, given
// with the measured first.
plot::Figure force_figure(const std::string& data) {
  return {.output = "force.png",
          .title = "preyield_hysteresis: the run's force",
          .panels = {{.x = {"displacement", "mm"},
                      .y = {"force", "kN"},
                      .data = {data, true},
                      .series = {{"measured", plot::column(2), plot::column(4).times(1e-3), plot::points(plot::colour::kDarkGrey),
                                  plot::Layer::measured},
                                 {"set aside", plot::column(2), plot::column(4).where(5, 0.5), plot::rings(plot::colour::kOrange),
                                  plot::Layer::note},
                                 {"base_model", plot::column(2), plot::column(3), plot::lines(plot::colour::kBlue)},
                                 {"", plot::column(2), plot::column(3).minus(4), plot::dashed(plot::colour::kRed)}}}}};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PlotScript, TextIsTakenLiterally) {
  const std::string script = plot::gnuplot_script(force_figure("run.csv"));
  EXPECT_NE(script.find("set terminal pngcairo noenhanced "), std::string::npos);
  // Underscores stay as written (noenhanced makes them literal, not subscripts); a quote is doubled.
  EXPECT_NE(script.find("set title 'preyield_hysteresis: the run''s force'\n"), std::string::npos);
  EXPECT_NE(script.find("title 'base_model'"), std::string::npos);
  EXPECT_EQ(script.find("\\_"), std::string::npos);
}

TEST(PlotScript, KeyOutsideTheDataAndHeadroomInsteadOfFixedRanges) {
  const std::string script = plot::gnuplot_script(force_figure("run.csv"));
  EXPECT_NE(script.find("set key below horizontal height 1\n"), std::string::npos);
  EXPECT_EQ(script.find("set key inside"), std::string::npos);
  EXPECT_NE(script.find("set offsets 0, 0, graph 0.05, graph 0.05\n"), std::string::npos);
  EXPECT_EQ(script.find("set yrange ["), std::string::npos);
  EXPECT_EQ(script.find("set xrange ["), std::string::npos);
  EXPECT_NE(script.find("set xlabel 'displacement [mm]'\nset ylabel 'force [kN]'\n"), std::string::npos);
}

TEST(PlotScript, AFixedRangeOnlyWhenAsked) {
  plot::Figure figure = force_figure("run.dat");
  figure.panels[0].y.range = plot::Range{-1.0, 1.0};
  figure.panels[0].y.log = true;
  const std::string script = plot::gnuplot_script(figure);
  EXPECT_NE(script.find("set yrange [-1:1]\n"), std::string::npos);
  EXPECT_NE(script.find("set logscale y\nset format y '%g'\n"), std::string::npos);
  EXPECT_EQ(script.find("set xrange ["), std::string::npos);
  EXPECT_EQ(script.find("set format x"), std::string::npos);
}

TEST(PlotScript, TheMeasuredIsDrawnOverTheModelsAndNotesOverIt) {
  const std::string script = plot::gnuplot_script(force_figure("run.csv"));
  const auto model = script.find("title 'base_model'");
  const auto unnamed = script.find("notitle");
  const auto measured = script.find("title 'measured'");
  const auto note = script.find("title 'set aside'");
  ASSERT_NE(model, std::string::npos);
  EXPECT_LT(model, unnamed);  // the models keep their order among themselves
  EXPECT_LT(unnamed, measured);
  EXPECT_LT(measured, note);
  EXPECT_EQ(count(script, "plot 'run.csv'"), 1u);  // one plot, every series from the same file
}

TEST(PlotScript, ColumnsTheirArithmeticAndStyles) {
  const std::string script = plot::gnuplot_script(force_figure("run.csv"));
  EXPECT_NE(script.find("using 2:($4*0.001) with points pt 7 ps 0.2 lc rgb '#555555' title 'measured'"), std::string::npos);
  EXPECT_NE(script.find("using 2:($5>=0.5?$4:1/0) with points pt 6 ps 0.5 lc rgb '#ff7f0e'"), std::string::npos);
  EXPECT_NE(script.find("using 2:3 with lines lw 1 lc rgb '#1f77b4'"), std::string::npos);
  EXPECT_NE(script.find("using 2:($3-$4) with lines lw 1 dt 2 lc rgb '#d62728' notitle"), std::string::npos);
  const std::string gated = plot::gnuplot_script(
      {.output = "x.png", .panels = {{.data = {"x.dat"}, .series = {{"gated", plot::column(3).where(1, 2.0, 8.0), plot::column(4)}}}}});
  EXPECT_NE(gated.find("plot 'x.dat' using ($1>=2&&$1<=8?$3:1/0):4 with lines lw 1 title 'gated'\n"), std::string::npos);
  const std::string error = plot::gnuplot_script(
      {.output = "x.png", .panels = {{.data = {"x.dat"}, .series = {{"e", plot::column(1), plot::column(9).minus(4).times(1e-3)}}}}});
  EXPECT_NE(error.find("using 1:(($9-$4)*0.001) "), std::string::npos);
}

TEST(PlotScript, ACsvIsReadWithItsColumnLineAndAnSvgIsVector) {
  const std::string csv = plot::gnuplot_script(force_figure("run.csv"));
  EXPECT_NE(csv.find("set datafile separator ','\nset datafile columnheaders\n"), std::string::npos);
  plot::Figure figure = force_figure("run.dat");
  figure.output = "force.svg";
  figure.panels[0].data.csv = false;
  const std::string svg = plot::gnuplot_script(figure);
  EXPECT_NE(svg.find("set terminal svg noenhanced "), std::string::npos);
  EXPECT_EQ(svg.find("set datafile"), std::string::npos);  // gnuplot's own: whitespace, '#' comments
}

TEST(PlotScript, PanelsShareAFigureTitleAndCarryNothingOver) {
  plot::Figure figure = force_figure("run.csv");
  figure.columns = 2;
  figure.panels.push_back({.title = "second",
                           .x = {"time", "s", plot::Range{2.0, 8.0}},
                           .y = {"count", ""},
                           .data = {"run.csv", true},
                           .series = {{"n", plot::column(1), plot::column(2)}},
                           .markers = {{0.0, "first run", false}, {5.0, "second run's"}}});
  figure.panels.push_back({.data = {"other.dat"}, .series = {{"m", plot::column(1), plot::column(2)}}});
  const std::string script = plot::gnuplot_script(figure);
  EXPECT_NE(script.find("set multiplot layout 2,2 title 'preyield_hysteresis: the run''s force'\n"), std::string::npos);
  EXPECT_EQ(count(script, "unset arrow\nunset label\nunset logscale\nset autoscale\nset format\n"), 2u);
  EXPECT_NE(script.find("set title 'second'\n"), std::string::npos);
  EXPECT_NE(script.find("unset title\n"), std::string::npos);
  EXPECT_NE(script.find("set xrange [2:8]\n"), std::string::npos);
  EXPECT_NE(script.find("set ylabel 'count'\n"), std::string::npos);
  EXPECT_EQ(count(script, "set arrow from"), 1u);  // the first run begins at the axis: its name only
  EXPECT_NE(script.find("set label 'second run''s' at 5, graph 0.97"), std::string::npos);
  EXPECT_NE(script.find("set datafile separator whitespace\nset datafile nocolumnheaders\n"), std::string::npos);
  EXPECT_NE(script.rfind("unset multiplot\nunset output\n"), std::string::npos);
}

TEST(PlotScript, CommentLinesComeFirst) {
  plot::Figure figure = force_figure("run.csv");
  figure.comment = "force against displacement\nredraw: gnuplot force.gp";
  EXPECT_EQ(plot::gnuplot_script(figure).rfind("# force against displacement\n# redraw: gnuplot force.gp\nset terminal", 0),
            0u);
}

// gnuplot itself reads what the module writes (skipped without gnuplot).
// A scatter of dots keeps its dots, and its key shows a point of its colour (a dot is a pixel).
TEST(PlotScript, ATitledSeriesOfDotsIsKeyedByAPointOfItsColour) {
  plot::Figure figure = force_figure("run.csv");
  figure.panels[0].series.push_back({"delivered", plot::column(2), plot::column(3), plot::dots(plot::colour::kBlue)});
  const std::string script = plot::gnuplot_script(figure);
  EXPECT_NE(script.find("using 2:3 with dots lc rgb '#1f77b4' notitle"), std::string::npos) << script;
  EXPECT_NE(script.find("NaN with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'delivered'\n"), std::string::npos) << script;
  EXPECT_EQ(count(script, "title 'delivered'"), 1u) << script;
}

TEST(PlotScript, GnuplotDrawsTheFigures) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  const auto dir = std::filesystem::temp_directory_path() / "mrd_plot_script";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "run.csv") << "time_s,displacement_mm,force_N,measured_force_N,aside_flag\n"
                                    "0,0,0,100,0\n0.1,1,1400,1300,1\n0.2,2,900,950,0\n";
  plot::Figure csv_figure = force_figure((dir / "run.csv").string());
  csv_figure.panels[0].series.push_back({"delivered", plot::column(2), plot::column(3), plot::dots(plot::colour::kBlue)});
  csv_figure.output = (dir / "force.png").string();
  ASSERT_EQ(plot::draw({csv_figure}), "");
  EXPECT_GT(std::filesystem::file_size(dir / "force.png"), 1000u);
  // A report's script: files named relative to its folder, a log axis, an SVG.
  std::ofstream(dir / "loops.dat") << "# H_A_per_m B_T\n1 0.1\n2 1\n3 1.4\n";
  std::ofstream(dir / "loops.gp") << plot::gnuplot_script(
      {.output = "loops.svg",
       .panels = {{.x = {"H", "A/m"},
                   .y = {"B", "T", std::nullopt, true},
                   .data = {"loops.dat"},
                   .series = {{"B", plot::column(1), plot::column(2), plot::steps()}}}}});
  ASSERT_EQ(plot::draw_scripts(dir.string(), {"loops"}), "");
  EXPECT_GT(std::filesystem::file_size(dir / "loops.svg"), 1000u);
  std::ofstream(dir / "broken.gp") << "plot 'missing.dat' using 1:2\n";
  EXPECT_NE(plot::draw_scripts(dir.string(), {"broken"}), "");
}

}  // namespace plot_script_test
