#include "record/candump_log.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "record/csv.hpp"

namespace mrd::record {

namespace {

namespace can = hal::can;

constexpr std::uint32_t kErrorFrameFlag = 0x20000000;  // CAN_ERR_FLAG, as candump prints it
constexpr std::uint32_t kMaxStandardId = 0x7FF;
constexpr std::uint32_t kMaxExtendedId = 0x1FFFFFFF;
constexpr std::size_t kMaxFdLength = 64;

struct LogFrame {
  std::uint32_t id = 0;
  bool extended = false;
  bool remote = false;
  bool fd = false;
  bool error = false;
  std::array<std::uint8_t, kMaxFdLength> data{};
  std::size_t length = 0;
};

enum class EventKind : std::uint8_t { kLvdt, kCommand, kFeedback };

struct Event {
  EventKind kind;
  double time;   // [s] from the log's first frame
  double value;  // [m] or [A]
  std::size_t line;
  std::string_view stamp;  // as written, for messages
};

std::optional<std::uint8_t> hex_digit(char c) {
  if (c >= '0' && c <= '9') return static_cast<std::uint8_t>(c - '0');
  if (c >= 'a' && c <= 'f') return static_cast<std::uint8_t>(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return static_cast<std::uint8_t>(c - 'A' + 10);
  return std::nullopt;
}

class CandumpParser {
 public:
  CandumpParser(std::string_view text, const std::string& name, const RunReadOptions& options)
      : lines_(text, name), name_(name), options_(options) {}

  CandumpLog parse() {
    if (options_.columns)
      throw InputError(name_ + ": --columns is for CSV files, not candump logs");
    if (options_.sample_rate)
      throw InputError(name_ + ": --sample-rate is for CSV files, not candump logs");
    while (const auto line = lines_.next()) read_line(*line);
    return build();
  }

 private:
  InputError fail(std::string_view column, const std::string& message) const {
    return InputError(input_error_message(name_, lines_.line_number(), column, message));
  }

  void read_line(std::string_view line) {
    const auto tokens = split_csv_line(line, Delimiter::kBlanks);
    const double time = read_timestamp(tokens[0]);
    const std::string_view stamp = tokens[0].substr(1, tokens[0].size() - 2);
    if (tokens.size() < 2) throw fail("interface", "missing: expected '(time) interface id#data'");
    if (tokens.size() < 3) throw fail("frame", "missing: expected '(time) interface id#data'");
    if (tokens.size() > 4 || (tokens.size() == 4 && tokens[3] != "R" && tokens[3] != "T")) {
      throw fail("frame", "unexpected text after the frame: '" + std::string(tokens[3]) + "'");
    }
    const LogFrame frame = read_frame(tokens[2]);
    const bool ours_kind =
        !frame.remote && !frame.fd && !frame.error && frame.extended == options_.can.extended_ids;
    const std::span<const std::uint8_t> data(frame.data.data(), frame.length);
    const auto& ids = options_.can;
    const Event event{EventKind::kLvdt, time, 0.0, lines_.line_number(), stamp};
    if (ours_kind && frame.id == ids.lvdt_id) {
      const auto d = can::decode_lvdt(frame.id, data, ids.lvdt_id, &lvdt_counter_);
      if (accept(d.status) && !flag_sensor_fault(d.value.sensor_fault)) {
        take(event, EventKind::kLvdt, d.value.displacement, stats_.lvdt_frames);
      }
    } else if (ours_kind && frame.id == ids.command_id) {
      const auto d = can::decode_command(frame.id, data, ids.command_id, &command_counter_);
      if (accept(d.status))
        take(event, EventKind::kCommand, d.value.setpoint, stats_.command_frames);
    } else if (ours_kind && ids.use_feedback && frame.id == ids.feedback_id) {
      const auto d = can::decode_feedback(frame.id, data, ids.feedback_id, &feedback_counter_);
      if (accept(d.status))
        take(event, EventKind::kFeedback, d.value.measured, stats_.feedback_frames);
    } else {
      ++stats_.other_frames;
    }
  }

  void take(Event event, EventKind kind, double value, std::size_t& count) {
    event.kind = kind;
    event.value = value;
    events_.push_back(event);
    ++count;
  }

  // "(1700000000.123456)" -> seconds from the log's first frame. Whole seconds and the
  // fraction are kept apart so the epoch does not eat the microseconds of a double.
  double read_timestamp(std::string_view token) {
    if (token.size() < 3 || token.front() != '(' || token.back() != ')') {
      throw fail("timestamp",
                 "expected '(seconds.microseconds)', got '" + std::string(token) + "'");
    }
    const std::string_view inside = token.substr(1, token.size() - 2);
    const auto dot = inside.find('.');
    const std::string_view whole = inside.substr(0, dot);
    const std::string_view fraction =
        dot == std::string_view::npos ? std::string_view{} : inside.substr(dot + 1);
    std::int64_t seconds = 0, fraction_count = 0;
    const auto [end, ec] = std::from_chars(whole.data(), whole.data() + whole.size(), seconds);
    const bool whole_ok = ec == std::errc{} && end == whole.data() + whole.size() && seconds >= 0;
    const auto [fend, fec] =
        std::from_chars(fraction.data(), fraction.data() + fraction.size(), fraction_count);
    const bool fraction_ok = dot == std::string_view::npos ||
                             (!fraction.empty() && fraction.size() <= 9 && fec == std::errc{} &&
                              fend == fraction.data() + fraction.size() &&
                              fraction.front() != '-' && fraction.front() != '+');
    if (!whole_ok || !fraction_ok) {
      throw fail("timestamp", "'" + std::string(inside) + "' is not seconds.microseconds");
    }
    double scale = 1.0;
    for (std::size_t i = 0; i < fraction.size(); ++i) scale *= 10.0;
    const double fraction_s = static_cast<double>(fraction_count) / scale;
    if (!epoch_) epoch_ = {seconds, fraction_s};
    const double t = static_cast<double>(seconds - epoch_->first) + (fraction_s - epoch_->second);
    if (t < last_time_) {
      throw fail("timestamp", "time goes backwards: " + std::string(inside) + " after " +
                                  std::string(last_stamp_));
    }
    last_time_ = t;
    last_stamp_ = inside;
    return t;
  }

  // "110#0123456789ABCDEF", "1F334455#", "123#R", "123##1AABB", "20000004#0004..."
  LogFrame read_frame(std::string_view token) {
    LogFrame f;
    const auto hash = token.find('#');
    if (hash == std::string_view::npos)
      throw fail("frame", "expected id#data, got '" + std::string(token) + "'");
    const std::string_view id = token.substr(0, hash);
    if (id.size() != 3 && id.size() != 8) {
      throw fail("frame",
                 "id '" + std::string(id) + "' must be 3 hex digits (11-bit) or 8 (29-bit)");
    }
    for (const char c : id) {
      const auto d = hex_digit(c);
      if (!d) throw fail("frame", "id '" + std::string(id) + "' is not hexadecimal");
      f.id = (f.id << 4) | *d;
    }
    f.extended = id.size() == 8;
    f.error = f.extended && (f.id & kErrorFrameFlag) != 0;
    if ((!f.extended && f.id > kMaxStandardId) ||
        (f.extended && !f.error && f.id > kMaxExtendedId)) {
      throw fail("frame", "id '" + std::string(id) + "' is out of range");
    }
    std::string_view data = token.substr(hash + 1);
    std::size_t max_length = can::kFrameLength;
    if (!data.empty() && data.front() == '#') {  // CAN FD: a flags digit, then up to 64 bytes
      f.fd = true;
      max_length = kMaxFdLength;
      if (data.size() < 2 || !hex_digit(data[1]))
        throw fail("frame", "CAN FD frame without its flags digit");
      data.remove_prefix(2);
    } else if (!data.empty() && (data.front() == 'R' || data.front() == 'r')) {
      f.remote = true;
      if (data.size() > 2 || (data.size() == 2 && !hex_digit(data[1]))) {
        throw fail("frame", "remote frame: expected R or R<length digit>");
      }
      return f;
    }
    if (data.size() % 2 != 0)
      throw fail("frame", "odd number of hex digits in the data '" + std::string(data) + "'");
    if (data.size() / 2 > max_length) {
      throw fail("frame", std::to_string(data.size() / 2) + " data bytes; at most " +
                              std::to_string(max_length));
    }
    for (std::size_t i = 0; i < data.size(); i += 2) {
      const auto hi = hex_digit(data[i]), lo = hex_digit(data[i + 1]);
      if (!hi || !lo) throw fail("frame", "data '" + std::string(data) + "' is not hexadecimal");
      f.data[f.length++] = static_cast<std::uint8_t>(*hi << 4 | *lo);
    }
    return f;
  }

  // Counts a frame the codec refuses, as the controller's receive path does.
  bool accept(can::DecodeStatus status) {
    switch (status) {
      case can::DecodeStatus::kOk: return true;
      case can::DecodeStatus::kOutOfSequence: ++stats_.sequence_gaps; return true;
      case can::DecodeStatus::kWrongDlc: ++stats_.wrong_dlc; break;
      case can::DecodeStatus::kBadChecksum: ++stats_.bad_checksum; break;
      case can::DecodeStatus::kRepeatedCounter: ++stats_.repeated_counter; break;
      case can::DecodeStatus::kWrongId: break;  // not reached: the id was matched first
    }
    note_dropped();
    return false;
  }

  bool flag_sensor_fault(bool fault) {
    if (!fault) return false;
    ++stats_.sensor_fault;
    note_dropped();
    return true;
  }

  void note_dropped() {
    if (stats_.first_dropped_line == 0) stats_.first_dropped_line = lines_.line_number();
  }

  CandumpLog build() {
    CandumpLog log;
    RecordedRun& run = log.run;
    run.name = name_;
    char text[128];
    if (stats_.lvdt_frames == 0) {
      std::snprintf(text, sizeof text, ": no usable LVDT frames (id 0x%X)", options_.can.lvdt_id);
      throw InputError(name_ + text);
    }
    const auto constant = constant_current(options_, name_);
    const bool any_frames = stats_.feedback_frames + stats_.command_frames > 0;
    if (constant && any_frames) {
      throw InputError(name_ +
                       ": the log has current frames; --current and --current-from-name are for "
                       "logs without them");
    }
    if (!constant && !any_frames) {
      std::snprintf(text, sizeof text,
                    ": no current frames (command 0x%X, feedback 0x%X); give --current",
                    options_.can.command_id, options_.can.feedback_id);
      throw InputError(name_ + text);
    }
    const EventKind source =
        stats_.feedback_frames > 0 ? EventKind::kFeedback : EventKind::kCommand;
    run.coil_source = constant                         ? constant->source
                      : source == EventKind::kFeedback ? "Coil_CurrentFeedback (measured current)"
                                                       : "Coil_CurrentCommand (commanded current)";
    std::optional<double> current;
    if (constant) current = constant->amps;
    for (const Event& e : events_) {
      if (e.kind == source && !constant) current = e.value;
      if (e.kind != EventKind::kLvdt) continue;
      if (!current) {
        ++stats_.samples_before_current;
        continue;
      }
      if (!run.time.empty() && !(e.time > run.time.back())) {
        throw InputError(
            input_error_message(name_, e.line, "timestamp",
                                "LVDT time does not increase: " + std::string(e.stamp) + " again"));
      }
      run.time.push_back(e.time);
      run.displacement.push_back(e.value);
      run.coil.push_back(*current);
    }
    if (run.size() < 2) {
      throw InputError(name_ + ": a run needs at least 2 LVDT samples with a known current, got " +
                       std::to_string(run.size()));
    }
    run.sample_rate = nominal_sample_rate(run.time);
    run.notes.push_back(stats_.summary());
    log.stats = stats_;
    return log;
  }

  LineReader lines_;
  const std::string& name_;
  const RunReadOptions& options_;
  CandumpStats stats_;
  std::vector<Event> events_;
  can::RollingCounterCheck lvdt_counter_, command_counter_, feedback_counter_;
  std::optional<std::pair<std::int64_t, double>> epoch_;  // the first frame's time
  double last_time_ = 0.0;
  std::string_view last_stamp_;
};

}  // namespace

std::string CandumpStats::summary() const {
  char text[400];
  std::snprintf(
      text, sizeof text,
      "candump: %zu LVDT, %zu command, %zu feedback frames used; dropped %zu "
      "(bad checksum %zu, wrong DLC %zu, repeated counter %zu, sensor fault %zu)%s; "
      "%zu counter gaps; %zu other frames ignored; %zu LVDT samples before the first "
      "current frame left out",
      lvdt_frames, command_frames, feedback_frames, dropped(), bad_checksum, wrong_dlc,
      repeated_counter, sensor_fault,
      first_dropped_line ? (", first at line " + std::to_string(first_dropped_line)).c_str() : "",
      sequence_gaps, other_frames, samples_before_current);
  return text;
}

CandumpLog parse_candump(std::string_view text, const std::string& name,
                         const RunReadOptions& options) {
  return CandumpParser(text, name, options).parse();
}

std::string candump_line(std::int64_t seconds, std::int64_t microseconds,
                         std::string_view interface, const hal::can::Frame& frame, bool extended) {
  char text[32];
  std::snprintf(text, sizeof text, "(%lld.%06lld) ", static_cast<long long>(seconds),
                static_cast<long long>(microseconds));
  std::string out = text;
  out.append(interface);
  std::snprintf(text, sizeof text, extended ? " %08X#" : " %03X#", frame.id);
  out += text;
  for (const std::uint8_t b : frame.data) {
    std::snprintf(text, sizeof text, "%02X", b);
    out += text;
  }
  return out;
}

std::string format_candump(const RecordedRun& run, std::optional<double> amps_per_volt,
                           const hal::can::SocketCanConfig& can, std::string_view interface) {
  const bool voltage = run.coil_signal == CoilSignal::kCommandVoltage;
  if (voltage && !amps_per_volt) {
    throw InputError(run.name +
                     ": the run logged the driver's command voltage; the log carries the "
                     "current: give the driver gain (--amps-per-volt)");
  }
  const double gain = voltage ? *amps_per_volt : 1.0;
  std::string out;
  for (std::size_t i = 0; i < run.size(); ++i) {
    const auto counter = static_cast<std::uint8_t>(i & 0x0F);
    const auto feedback =
        can::encode_feedback(can.feedback_id, {run.coil[i] * gain, false, counter});
    const auto lvdt = can::encode_lvdt(can.lvdt_id, {run.displacement[i], false, counter});
    if (feedback.status != can::EncodeStatus::kOk || lvdt.status != can::EncodeStatus::kOk) {
      throw InputError(run.name + ": sample " + std::to_string(i + 1) +
                       " does not fit the CAN frames (displacement or current out of range)");
    }
    const auto us = std::llround((run.time[i] - run.time[0]) * 1e6);
    for (const auto* frame : {&feedback.frame, &lvdt.frame}) {
      out += candump_line(us / 1000000, us % 1000000, interface, *frame, can.extended_ids) + '\n';
    }
  }
  return out;
}

}  // namespace mrd::record
