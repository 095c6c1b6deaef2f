#pragma once

namespace mrd::cli {

// The exit status of every mrd program: one meaning per code, whatever the tool, stated in
// every --help footer (docs/ARCHITECTURE.md, "Command-line programs").
enum ExitCode : int {
  kOk = 0,
  kUsage = 1,     // a bad command line or config (CLI11's parse errors among them)
  kBadInput = 2,  // an input file (or, for --probe, the readings) that is malformed or wrong
  kIo = 3,        // a file, folder or bus that cannot be opened or written
  kEndedSafe = 4, // mrd-controller: the run ended in SAFE through a fault, not through the stop
};

}  // namespace mrd::cli
