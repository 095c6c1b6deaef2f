#include "firmware/hal_set.hpp"

namespace mrd::firmware {

// With a CAN driver the command frame carries DriverEnable and the feedback frame DriverFault:
// the lines back end is mirrored into and combined with them.
class HalSet::CanEnableLines final : public hal::DigitalLines {
 public:
  CanEnableLines(hal::DigitalLines& lines, hal::can::SocketCanBackend& can) : lines_(lines), can_(can) {}
  hal::IoStatus set_enable(bool enabled) override {
    can_.set_command_enable(enabled);
    return lines_.set_enable(enabled);
  }
  std::optional<bool> driver_fault() override {
    const std::optional<bool> line = lines_.driver_fault();
    if (line && !*line && can_.feedback_driver_fault().value_or(false)) return true;
    return line;
  }

 protected:
  hal::IoStatus write_heartbeat(bool high) override { return lines_.set_heartbeat(high); }

 private:
  hal::DigitalLines& lines_;
  hal::can::SocketCanBackend& can_;
};

namespace {

template <typename Device>
Device* choose(config::DeviceBackend which, Device* mock, Device* modbus, Device* can) {
  switch (which) {
    case config::DeviceBackend::kMock: return mock;
    case config::DeviceBackend::kModbus: return modbus;
    case config::DeviceBackend::kCan: return can;
  }
  return nullptr;
}

template <typename Event, typename Snapshot>
void append_counters(std::string& out, std::string_view name, const Snapshot& counters) {
  out += name;
  out += ':';
  for (std::size_t i = 0; i < static_cast<std::size_t>(Event::kCount); ++i) {
    const auto e = static_cast<Event>(i);
    out += ' ';
    out += to_string(e);
    out += '=';
    out += std::to_string(counters[e]);
  }
  out += '\n';
}

}  // namespace

HalSet::HalSet(const config::ControllerConfig& config, const hal::Clock& clock) {
  const auto& b = config.backends;
  if (b.any_mock()) mock_ = std::make_unique<hal::mock::MockHal>();
  if (b.uses(config::DeviceBackend::kModbus)) {
    modbus_ = std::make_unique<hal::modbus::ModbusBackend>(config.modbus, clock);
  }
  if (b.uses(config::DeviceBackend::kCan)) can_ = std::make_unique<hal::can::SocketCanBackend>(config.can, clock);
  can_lvdt_ = b.lvdt == config::DeviceBackend::kCan;
  can_feedback_ = b.driver == config::DeviceBackend::kCan && config.can.use_feedback;
  if (b.lines == config::LinesBackend::kGpio) gpio_ = std::make_unique<hal::gpio::GpiodLines>(config.gpio);

  hal::mock::MockHal* const mock = mock_.get();
  hal::modbus::ModbusBackend* const modbus = modbus_.get();
  hal::can::SocketCanBackend* const can = can_.get();
  lvdt_ = choose<hal::SampleSource>(b.lvdt, mock ? &mock->lvdt : nullptr, modbus ? &modbus->lvdt() : nullptr,
                                    can ? &can->lvdt() : nullptr);
  driver_ = choose<hal::CurrentDriver>(b.driver, mock ? &mock->driver : nullptr, modbus, can);
  if (b.demand) {
    demand_ = choose<hal::SampleSource>(*b.demand, mock ? &mock->demand : nullptr,
                                        modbus ? &modbus->demand() : nullptr, can ? &can->demand() : nullptr);
  }
  if (b.load_cell) {
    load_cell_ = choose<hal::SampleSource>(*b.load_cell, mock ? &mock->load_cell : nullptr,
                                           modbus ? &modbus->load_cell() : nullptr, can ? &can->load_cell() : nullptr);
  }
  if (modbus_) threads_.push_back(&modbus_->io_thread());
  if (can_) threads_.push_back(&can_->io_thread());
  lines_ = gpio_ ? static_cast<hal::DigitalLines*>(gpio_.get()) : &mock_->lines;
  if (b.driver == config::DeviceBackend::kCan) {
    can_enable_ = std::make_unique<CanEnableLines>(*lines_, *can_);
    lines_ = can_enable_.get();
  }
}

HalSet::~HalSet() { stop(); }

hal::StartResult HalSet::start() {
  std::string errors;
  const auto collect = [&errors](std::string_view who, const hal::StartResult& r) {
    if (!r.ok) errors += std::string(who) + ": " + r.error + (r.error.ends_with('\n') ? "" : "\n");
  };
  if (modbus_) collect("modbus", modbus_->start());
  if (can_) collect("can", can_->start());
  if (gpio_) collect("gpio", gpio_->start());
  return errors.empty() ? hal::StartResult::success() : hal::StartResult::failure(errors);
}

void HalSet::stop() {
  if (modbus_) modbus_->stop();
  if (can_) can_->stop();
}

std::string HalSet::counters() const {
  std::string out;
  if (modbus_) append_counters<hal::modbus::ModbusEvent>(out, "modbus", modbus_->counters());
  if (can_) append_counters<hal::can::CanEvent>(out, "can", can_->counters());
  return out;
}

bool HalSet::link_never_up() const { return modbus_ && modbus_->never_connected(); }

std::vector<std::string> HalSet::link_problems() const {
  std::vector<std::string> out;
  if (modbus_) {
    if (const auto problem = modbus_->link_problem()) out.push_back("modbus: " + *problem);
  }
  if (can_) {
    if (const auto problem = can_->link_problem(can_lvdt_, can_feedback_)) out.push_back("can: " + *problem);
  }
  return out;
}

}  // namespace mrd::firmware
