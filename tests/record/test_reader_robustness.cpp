// Issue 6 fuzzes the readers; until then, a seeded mutation pass asserts the contract that
// matters: whatever the bytes, a reader returns a run or throws InputError, and never crashes.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "hal/can/can_codec.hpp"
#include "record/csv.hpp"
#include "record/candump_log.hpp"
#include "record/run_reader.hpp"

namespace {

using mrd::record::InputError;

std::string mutate(std::string text, std::mt19937& rng) {
  static constexpr char kAlphabet[] = "0123456789.,-+eE#() \n\t\"xAnaifR_";
  std::uniform_int_distribution<int> edits(1, 6);
  for (int e = edits(rng); e > 0 && !text.empty(); --e) {
    std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
    std::uniform_int_distribution<std::size_t> pick(0, sizeof kAlphabet - 2);
    switch (rng() % 4) {
      case 0: text[at(rng)] = kAlphabet[pick(rng)]; break;
      case 1: text.insert(at(rng), 1, kAlphabet[pick(rng)]); break;
      case 2: text.erase(at(rng), 1 + rng() % 8); break;
      default: text.resize(at(rng)); break;
    }
  }
  return text;
}

void survives(const std::string& seed_text, const mrd::record::RunReadOptions& options) {
  std::mt19937 rng(7);
  for (int i = 0; i < 3000; ++i) {
    const std::string text = mutate(seed_text, rng);
    try {
      (void)mrd::record::parse_recorded_run(text, "fuzz", options);
    } catch (const InputError&) {
    }
  }
}

TEST(RunReaders, MutatedOwnCsvNeverCrashes) {
  survives(
      "time_s,displacement_mm,current_A,force_kN,velocity_mm_s\n0,1,0.5,1,2\n0.001,2,0.5,1.1,3\n"
      "0.002,3,0.5,1.2,4\n",
      {});
}

TEST(RunReaders, MutatedForeignFilesNeverCrash) {
  mrd::record::RunReadOptions dyke;
  dyke.columns =
      mrd::record::parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N");
  survives(
      "\"t\",\"A\",\"D\",\"Y\",\"fs\",\"V\",\"F\",\n0,-32.3,0.021,2.25,3004.8,7.8,946.9,\n"
      "0.0003328,-31.0,0.023,2.25,,7.5,945.2,\n0.0006656,-29.5,0.026,2.25,,7.3,943.2,\n",
      dyke);
  mrd::record::RunReadOptions quiroz;
  quiroz.columns =
      mrd::record::parse_column_mapping("1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N");
  quiroz.current = 0.5;
  survives("  0.0e+00 -1.02e-01 1.08e+00 -1.46e+01\n  5.0e-03 -9.67e-02 1.16e+00 -1.11e+01\n",
           quiroz);
}

TEST(RunReaders, MutatedCandumpLogsNeverCrash) {
  namespace can = mrd::hal::can;
  std::string log;
  for (std::uint8_t i = 0; i < 6; ++i) {
    const auto t = 100000 + 1000 * i;
    log += mrd::record::candump_line(
               1700000000, t, "vcan0",
               can::encode_command(can::kDefaultCommandId, {0.1 * i, true, i}).frame) +
           "\n";
    log += mrd::record::candump_line(
               1700000000, t + 500, "vcan0",
               can::encode_lvdt(can::kDefaultLvdtId, {0.001 * i, false, i}).frame) +
           "\n";
  }
  survives(log, {});
}

}  // namespace
