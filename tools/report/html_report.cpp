#include "tools/report/html_report.hpp"

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/cli/command_line.hpp"
#include "tools/gnuplot.hpp"
#include "tools/report/sha256.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace fs = std::filesystem;

namespace {

std::string number_cell(const std::string& key, double value);

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 8px;text-align:left}"
    "td.num{text-align:right;font-family:monospace}caption{text-align:left;font-weight:bold;padding:4px 0}"
    "figure{margin:1em 0}figcaption{font-size:.9em;color:#555}svg{max-width:100%;height:auto}"
    "code{font-size:.9em;word-break:break-all}";

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
  const std::size_t rows = columns.empty() ? 0 : columns.front()->size();
  const std::size_t stride = std::max<std::size_t>(1, (rows + max_rows - 1) / std::max<std::size_t>(1, max_rows));
  std::ofstream out(fs::path(directory_) / file);
  out << "#";
  for (const auto& c : column_names) out << ' ' << c;
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
  if (!out && error_.empty()) error_ = "cannot write " + (fs::path(directory_) / file).string();
  return file;
}

void HtmlReport::plot(const std::string& name, const std::string& caption, const std::string& body) {
  plots_.emplace_back(pieces_.size(), Plot{name, caption, body});
  pieces_.emplace_back();
}

std::string HtmlReport::write() {
  if (!error_.empty()) return error_;
  std::string load;
  for (const auto& [at, p] : plots_) {
    const fs::path gp = fs::path(directory_) / (p.name + ".gp");
    std::ofstream out(gp);
    out << "# " << p.caption << "\n# redraw: gnuplot " << p.name << ".gp (in this directory)\n"
        << "set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'\n"
        << "set output '" << p.name << ".svg'\nset grid\nset key below horizontal noenhanced\n"
        << p.body << (p.body.empty() || p.body.back() == '\n' ? "" : "\n") << "unset output\n";
    if (!out) return "cannot write " + gp.string();
    load += "reset\nload '" + p.name + ".gp'\n";
  }
  std::string why;
  if (!plots_.empty()) {
    std::string dir = fs::absolute(directory_).string();
    std::string quoted;
    for (const char c : dir) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    why = run_gnuplot("cd '" + quoted + "'\n" + load);
  }
  for (const auto& [at, p] : plots_) {
    std::string svg = svg_element((fs::path(directory_) / (p.name + ".svg")).string());
    if (svg.empty()) svg = "<p>(plot not drawn: " + html_escape(why.empty() ? "no svg" : why) + ")</p>";
    pieces_[at] = "<figure id=\"" + html_escape(p.name) + "\">\n" + svg + "\n<figcaption>" + html_escape(p.caption) +
                  " (script: " + html_escape(p.name) + ".gp)</figcaption></figure>\n";
  }
  std::ofstream out(html_path());
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title_)
      << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << html_escape(title_) << "</h1>\n";
  for (const auto& piece : pieces_) out << piece;
  out << "</body>\n</html>\n";
  if (!out) return "cannot write " + html_path();
  return why;
}

}  // namespace mrd::tools
