#include "tools/replay/run_options_cli.hpp"

#include <cstdio>
#include <string_view>

#include "common/cli/command_line.hpp"
#include "record/csv.hpp"
#include "record/run_columns.hpp"

namespace mrd::tools {

void RunOptionsCli::add_to(CLI::App& app) {
  app.add_option("--columns", columns_,
                 "map a foreign file's columns: t=time_s,D=displacement_cm,... by header name, or "
                 "1=time_s,2=displacement_mm,... by position (no header). Text is split on the delimiter "
                 "its header uses (';' then decimal commas are read, ',', tab, or blanks). In a MATLAB .mat "
                 "file (v5, v7.3) the names are variables, a matrix column is name:k (data:2=force_N), "
                 "and Ts=sample_time_s or fs=sample_rate_Hz names a scalar that gives the time where "
                 "there is no time vector; without --columns the variables named by unit are read. "
                 "Units: " + record::known_unit_names())
      ->check(CLI::Validator(
          [](std::string& text) {
            try {
              (void)record::parse_column_mapping(text);
              return std::string();
            } catch (const record::InputError& e) {
              std::string_view why = e.what();  // CLI11 names the option itself
              if (why.starts_with("--columns: ")) why.remove_prefix(11);
              return std::string(why);
            }
          },
          "MAPPING"));
  current_option_ = app.add_option("--current", current_, "constant coil current of the run [A]")
                        ->check(cli::finite_in(-1000.0, 1000.0));
  auto* from_name = app.add_flag("--current-from-name", current_from_name_,
                                 "read the constant current from the file name (25mm0x25Hz0x5A.txt: 0.5 A)");
  current_option_->excludes(from_name);
  rate_option_ = app.add_option("--sample-rate", sample_rate_, "[Hz], for files without a time column")
                     ->check(cli::finite_in(1.0, 1e6));
  app.add_option("--config", config_path_, "the controller's TOML config (default: the embedded one)");
  gain_option_ = app.add_option("--amps-per-volt", amps_per_volt_,
                                "current driver gain [A/V], for runs that logged its command voltage")
                     ->check(cli::finite_in(1e-6, 1e6));
}

std::optional<config::LoadedConfig> RunOptionsCli::load_config() const {
  auto config = config_path_.empty() ? config::load_default_config() : config::load_config_file(config_path_);
  if (!config.ok()) {
    std::fprintf(stderr, "%s", config.report().c_str());
    return std::nullopt;
  }
  for (const auto& warning : config.warnings) std::fprintf(stderr, "%s\n", warning.to_string().c_str());
  return config;
}

record::RunReadOptions RunOptionsCli::read_options(const config::LoadedConfig& config) const {
  record::RunReadOptions read;
  read.can = config.config.can;
  read.current_from_name = current_from_name_;
  if (!columns_.empty()) read.columns = record::parse_column_mapping(columns_);
  if (current_option_ != nullptr && current_option_->count() > 0) read.current = current_;
  if (rate_option_ != nullptr && rate_option_->count() > 0) read.sample_rate = sample_rate_;
  return read;
}

std::optional<double> RunOptionsCli::amps_per_volt() const {
  if (gain_option_ != nullptr && gain_option_->count() > 0) return amps_per_volt_;
  return std::nullopt;
}

}  // namespace mrd::tools
