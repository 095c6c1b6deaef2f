#include "tools/report/html_report.hpp"

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/cli/program_outputs.hpp"
#include "tools/plot/gnuplot.hpp"
#include "tools/report/sha256.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace web {
extern const char kUplotJs[];
extern const char kUplotCss[];
extern const char kUplotLicence[];
extern const char kTimeChartJs[];
}  // namespace web

namespace fs = std::filesystem;

namespace {

std::string number_cell(const std::string& key, double value);

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 8px;text-align:left}"
    "td.num{text-align:right;font-family:monospace}caption{text-align:left;font-weight:bold;padding:4px 0}"
    "figure{margin:1em 0}figcaption{font-size:.9em;color:#555}svg{max-width:100%;height:auto}"
    "code{font-size:.9em;word-break:break-all}img.plot{max-width:100%;height:auto}.mrd-chart-plot{min-height:360px}";

std::string quote_shell(const std::string& arg) {
  if (!arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=:,+@%") ==
                          std::string::npos)
    return arg;
  std::string out = "'";
  for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The <svg> element of a gnuplot svg file (without its XML prologue and doctype).
std::string svg_element(const std::string& path) {
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto start = text.find("<svg");
  const auto end = text.rfind("</svg>");
  if (start == std::string::npos || end == std::string::npos) return {};
  return text.substr(start, end + 6 - start);
}

// A file's bytes, base64 (for an inlined PNG); "" when it cannot be read.
std::string base64_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return in.bad() || bytes.empty() ? std::string() : base64(bytes.data(), bytes.size());
}

// JSON inside <script>: a '<' could end the element or open a comment the parser then hides the
// page in ("</script", "<!--"); JSON's own escape keeps the text.
std::string script_safe(const std::string& json) {
  std::string out;
  for (const char c : json) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

// A number with its JSON key: the full value in data-value, six digits shown.
std::string number_cell(const std::string& key, double value) {
  const std::string keyed = key.empty() ? std::string()
                                         : " data-key=\"" + html_escape(key) + "\" data-value=\"" +
                                               (std::isfinite(value) ? format("%.17g", value) : std::string("nan")) + "\"";
  return "<td class=\"num\"" + keyed + ">" +
         (std::isfinite(value) ? format("%.6g", value) : std::string("&ndash;")) + "</td>";
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

Provenance provenance_of(const std::string& tool, int argc, const char* const* argv, std::vector<std::string> inputs,
                         std::string seed) {
  Provenance p{tool, {}, std::move(inputs), std::move(seed)};
  for (int i = 0; i < argc; ++i) {
    if (i > 0) p.command_line += ' ';
    p.command_line += quote_shell(argv[i]);
  }
  return p;
}

HtmlReport::HtmlReport(std::string title, std::string directory)
    : title_(std::move(title)), directory_(std::move(directory)) {
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec) error_ = "cannot create " + directory_ + ": " + ec.message();
}

std::string HtmlReport::html_path() const { return (fs::path(directory_) / "report.html").string(); }

void HtmlReport::heading(const std::string& text) { pieces_.push_back("<h2>" + html_escape(text) + "</h2>\n"); }

void HtmlReport::paragraph(const std::string& text) { pieces_.push_back("<p>" + html_escape(text) + "</p>\n"); }

void HtmlReport::figures(const std::string& caption, const std::vector<ReportFigure>& rows) {
  std::string out = "<table class=\"figures\"><caption>" + html_escape(caption) + "</caption>\n";
  for (const ReportFigure& f : rows) {
    out += "<tr><th>" + html_escape(f.label) + "</th>" + number_cell(f.key, f.value) + "<td>" + html_escape(f.unit) +
           "</td></tr>\n";
  }
  pieces_.push_back(out + "</table>\n");
}

void HtmlReport::parameters(const std::string& caption, const std::vector<Parameter>& rows) {
  std::string out = "<table class=\"parameters\"><caption>" + html_escape(caption) +
                    "</caption>\n<tr><th>parameter</th><th>value</th><th>standard deviation</th><th>relative</th>"
                    "<th>unit</th></tr>\n";
  for (const Parameter& p : rows) {
    const double relative = p.value != 0.0 ? 100.0 * p.standard_deviation / std::abs(p.value) : NAN;
    out += "<tr><th>" + html_escape(p.label) + "</th>" + number_cell(p.key, p.value) +
           number_cell(p.sd_key, p.standard_deviation) + "<td class=\"num\">" +
           (std::isfinite(relative) ? format("%.3g %%", relative) : std::string("&ndash;")) + "</td><td>" +
           html_escape(p.unit) + "</td></tr>\n";
  }
  pieces_.push_back(out + "</table>\n");
}

void HtmlReport::correlation_matrix(const std::string& caption, const std::vector<std::string>& names,
                                    const std::vector<std::vector<double>>& correlation) {
  std::string out = "<table class=\"correlation\"><caption>" + html_escape(caption) + "</caption>\n<tr><th></th>";
  for (std::size_t j = 0; j < names.size(); ++j) out += "<th title=\"" + html_escape(names[j]) + "\">" + std::to_string(j + 1) + "</th>";
  out += "</tr>\n";
  std::vector<std::vector<std::string>> close;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += "<tr><th>" + std::to_string(i + 1) + " " + html_escape(names[i]) + "</th>";
    for (std::size_t j = 0; j < names.size(); ++j) {
      const double r = i < correlation.size() && j < correlation[i].size() ? correlation[i][j] : NAN;
      if (!std::isfinite(r)) {
        out += "<td class=\"num\">&ndash;</td>";
        continue;
      }
      // White at 0, a deeper red as |r| grows: the strong couplings catch the eye first.
      const int light = static_cast<int>(std::lround(100.0 - 45.0 * std::min(1.0, std::abs(r))));
      out += format("<td class=\"num\" style=\"background:hsl(0,80%%,%d%%)\">%.2f</td>", light, r);
      if (j > i && std::abs(r) > 0.95) close.push_back({names[i], names[j], format("%.4f", r)});
    }
    out += "</tr>\n";
  }
  pieces_.push_back(out + "</table>\n");
  table("Pairs correlated beyond 0.95 (the run hardly separates them)", {"parameter", "parameter", "r"}, close);
}

void HtmlReport::table(const std::string& caption, const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  std::string out = "<table><caption>" + html_escape(caption) + "</caption>\n<tr>";
  for (const auto& h : header) out += "<th>" + html_escape(h) + "</th>";
  out += "</tr>\n";
  for (const auto& row : rows) {
    out += "<tr>";
    for (const auto& cell : row) out += "<td>" + html_escape(cell) + "</td>";
    out += "</tr>\n";
  }
  if (rows.empty()) out += "<tr><td colspan=\"" + std::to_string(std::max<std::size_t>(1, header.size())) + "\">none</td></tr>\n";
  pieces_.push_back(out + "</table>\n");
}

void HtmlReport::provenance(const Provenance& p) {
  heading("Provenance");
  std::vector<std::vector<std::string>> rows = {{"tool", p.tool + " " + mrd::cli::version()},
                                                {"command line", p.command_line}};
  if (!p.seed.empty()) rows.push_back({"seed", p.seed});
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  rows.push_back({"written", stamp});
  table("How this report was made", {"what", "value"}, rows);
  std::vector<std::vector<std::string>> files;
  for (const auto& path : p.inputs) {
    const std::string sum = sha256_file(path);
    files.push_back({path, sum.empty() ? "(unreadable)" : sum});
  }
  table("Input files", {"file", "SHA-256"}, files);
}

std::string HtmlReport::data(const std::string& name, const std::vector<std::string>& column_names,
                             const std::vector<const std::vector<double>*>& columns, std::size_t max_rows) {
  const std::string file = name + ".dat";
  const std::string why = plot::write_columns((fs::path(directory_) / file).string(), column_names, columns, max_rows);
  if (!why.empty() && error_.empty()) error_ = why;
  return file;
}

void HtmlReport::plot(const std::string& name, const std::string& caption, plot::Panel panel, Drawing drawing) {
  plots_.emplace_back(pieces_.size(), Plot{name, caption, std::move(panel), drawing});
  pieces_.emplace_back();
}

void HtmlReport::time_chart(const TimeChart& chart) {
  const Json data = time_chart_data(chart);
  const double per_point = data["samples_per_point"].get<double>();
  const std::string thinning =
      per_point > 1.0 ? format("; long run: each point pair is the min and max of %.3g samples", 2.0 * per_point) : "";
  pieces_.push_back("<figure class=\"mrd-chart\" id=\"" + html_escape(chart.name) +
                    "\">\n<div class=\"mrd-chart-plot\"></div>\n<script type=\"application/json\">" +
                    script_safe(data.dump(-1, ' ', false, Json::error_handler_t::replace)) + "</script>\n<figcaption>" + html_escape(chart.caption) +
                    " (drag to zoom, double-click for the whole run" + html_escape(thinning) + ")</figcaption></figure>\n");
  has_charts_ = true;
}

std::string HtmlReport::write() {
  if (!error_.empty()) return error_;
  std::vector<std::string> scripts;
  for (const auto& [at, p] : plots_) {
    const fs::path gp = fs::path(directory_) / (p.name + ".gp");
    const plot::Figure figure{.output = p.name + (p.drawing == Drawing::raster ? ".png" : ".svg"),
                              .width = 860,
                              .height = 440,
                              .panels = {p.panel},
                              .comment = p.caption + "\nredraw: gnuplot " + p.name + ".gp (in this directory)"};
    std::ofstream out(gp);
    out << plot::gnuplot_script(figure);
    if (!out) return "cannot write " + gp.string();
    scripts.push_back(p.name);
  }
  const std::string why = scripts.empty() ? std::string() : plot::draw_scripts(directory_, scripts);
  for (const auto& [at, p] : plots_) {
    std::string svg;
    if (p.drawing == Drawing::raster) {
      const std::string png = base64_file((fs::path(directory_) / (p.name + ".png")).string());
      if (!png.empty())
        svg = "<img class=\"plot\" width=\"860\" height=\"440\" alt=\"" + html_escape(p.caption) + "\" src=\"data:image/png;base64," + png + "\">";
    } else {
      svg = svg_element((fs::path(directory_) / (p.name + ".svg")).string());
    }
    if (svg.empty()) svg = "<p>(plot not drawn: " + html_escape(why.empty() ? "no image" : why) + ")</p>";
    pieces_[at] = "<figure id=\"" + html_escape(p.name) + "\">\n" + svg + "\n<figcaption>" + html_escape(p.caption) +
                  " (script: " + html_escape(p.name) + ".gp)</figcaption></figure>\n";
  }
  std::ofstream out(html_path());
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title_)
      << "</title>\n<style>" << kStyle << (has_charts_ ? web::kUplotCss : "") << "</style>\n</head>\n<body>\n<h1>"
      << html_escape(title_) << "</h1>\n";
  for (const auto& piece : pieces_) out << piece;
  // uPlot with its MIT licence, then the charts' own script, inlined.
  if (has_charts_)
    out << "<script>/*\n" << web::kUplotLicence << "*/\n" << web::kUplotJs << "</script>\n<script>" << web::kTimeChartJs
        << "</script>\n";
  out << "</body>\n</html>\n";
  if (!out) return "cannot write " + html_path();
  return why;
}

}  // namespace mrd::tools
