#include "tools/identification/identify_report.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/gnuplot.hpp"
#include "tools/json.hpp"

namespace mrd::tools {

namespace {

std::string params_json(const Point& x) {
  std::string out = "{";
  for (int j = 0; j < kParameterCount; ++j) {
    out += (j ? ", \"" : "\"") + std::string(kParameterNames[static_cast<std::size_t>(j)]) +
           "\": " + json_number(x[j]);
  }
  return out + "}";
}

}  // namespace

std::string identify_json(const IdentifyResult& r) {
  std::ostringstream out;
  out << "{\n  \"algo\": \"" << algorithm_name(r.algorithm) << "\",\n"
      << "  \"params\": " << params_json(r.search.best) << ",\n"
      << "  \"rmse_T\": " << json_number(r.fit.rmse) << ",\n"
      << "  \"evaluations\": " << r.search.evaluations << ",\n"
      << "  \"wall_s\": " << json_number(r.wall_s) << ",\n"
      << "  \"rounds\": " << r.rounds << ",\n"
      << "  \"start\": " << params_json(r.start) << ",\n"
      << "  \"bounds\": {\"lower\": " << params_json(r.bounds.lower)
      << ", \"upper\": " << params_json(r.bounds.upper) << "}";
  if (r.polish) {
    out << ",\n  \"polish\": {\"method\": \"levenberg-marquardt\", \"params\": "
        << params_json(r.polish->best) << ", \"rmse_T\": " << json_number(r.polish->rmse)
        << ", \"evaluations\": " << r.polish->evaluations
        << ", \"wall_s\": " << json_number(r.polish_wall_s) << "}";
  }
  out << "\n}\n";
  return out.str();
}

std::string identify_text(const IdentifyResult& r, const BHObjective& objective) {
  std::ostringstream out;
  const double rms = objective.rms_B();
  auto row = [&](const char* label, const Point& x, double rmse, std::int64_t evaluations,
                 double wall) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-14s Ms=%-11.5g a=%-10.5g alpha=%-11.5g k=%-10.5g c=%-8.5g | RMSE %.4g T "
                  "(%.3g%% of rms B) | %lld evaluations, %.3f s\n",
                  label, x[0], x[1], x[2], x[3], x[4], rmse, 100.0 * rmse / rms,
                  static_cast<long long>(evaluations), wall);
    out << line;
  };
  out << objective.points() << " points; rms B " << json_number(rms) << " T\n";
  if (r.rounds > 1) {
    out << "the best point reached a face of the estimated box; searched " << r.rounds
        << " boxes, each re-centred on the best so far\n";
  }
  out << "start          Ms=" << json_number(r.start[0]) << " a=" << json_number(r.start[1])
      << " alpha=" << json_number(r.start[2]) << " k=" << json_number(r.start[3])
      << " c=" << json_number(r.start[4]) << "\n";
  row(std::string(algorithm_name(r.algorithm)).c_str(), r.search.best, r.fit.rmse,
      r.search.evaluations, r.wall_s);
  if (r.fit.penalised) out << "warning: the best point is penalised (non-physical)\n";
  if (r.polish) row("+ LM polish", r.polish->best, r.polish->rmse, r.polish->evaluations, r.polish_wall_s);
  return out.str();
}

std::string plot_identification(const IdentifyResult& r, const BHObjective& objective,
                                const BHCurve& curve, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return "cannot create " + directory + ": " + ec.message();
  const Point& best = r.polish ? r.polish->best : r.search.best;
  const auto fitted = objective.simulate(to_params(best));
  const std::string loops_file = (fs::path(directory) / "identify_bh.dat").string();
  const std::string convergence_file = (fs::path(directory) / "identify_convergence.dat").string();
  {
    std::ofstream out(loops_file);
    std::size_t i = 0;
    for (const auto& loop : curve.loops) {
      for (std::size_t j = 0; j < loop.H.size(); ++j, ++i) {
        out << loop.H[j] << ' ' << loop.B[j] << ' ' << fitted[i] << '\n';
      }
      out << "\n\n";
    }
    std::ofstream conv(convergence_file);
    for (const auto& c : r.search.convergence) conv << c.evaluations << ' ' << c.best_fitness << '\n';
  }
  const std::string label = std::string(algorithm_name(r.algorithm)) + (r.polish ? " + LM" : "");
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,650\n"
     << "set output '" << (fs::path(directory) / "identify_bh.png").string() << "'\n"
     << "set title 'B-H loops: measured and fitted (" << label << ", RMSE "
     << json_number(r.polish ? r.polish->rmse : r.fit.rmse) << " T)' noenhanced\n"
     << "set xlabel 'H [A/m]'\nset ylabel 'B [T]'\nset grid\nset key left top\n"
     << "plot '" << loops_file << "' using 1:2 with points pt 7 ps 0.4 title 'measured', '"
     << loops_file << "' using 1:3 with lines lw 2 title 'J-A fit'\n"
     << "set output '" << (fs::path(directory) / "identify_convergence.png").string() << "'\n"
     << "set title 'Convergence (" << label << ")' noenhanced\n"
     << "set xlabel 'evaluations'\nset ylabel 'best fitness [T]'\nset logscale y\n"
     << "plot '" << convergence_file << "' using 1:2 with steps lw 2 title 'global best'\n";
  return run_gnuplot(gp.str());
}

}  // namespace mrd::tools
