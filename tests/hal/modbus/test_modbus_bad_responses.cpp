// Bad Modbus responses end to end (docs/RELIABILITY.md): a forging TCP server on 127.0.0.1
// answers the back end's LVDT reads with short, mislabelled and exception responses. The
// documented reaction: a response that is not a well-formed answer to the request is a link
// failure (counted as a read error, the link closed and reopened with back-off); an exception
// response is the device's answer, counted with the link kept; none of them ever yields a
// sample, so the loop sees the LVDT go stale.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>

#include "hal/modbus/modbus_backend.hpp"
#include "tests/hal/modbus/modbus_test_server.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using mrd::hal::MonotonicClock;
using mrd::hal::modbus::ModbusBackend;
using mrd::hal::modbus::ModbusEvent;
using mrd::test::ModbusTestServer;
using mrd::test::tcp_response;
using mrd::test::wait_for;

using Request = std::span<const std::uint8_t>;
constexpr std::size_t kFunction = 7;  // after the 7-byte MBAP header

// Runs the back end against `forge` until it has counted `reads` read errors; returns its
// counters then, after checking that no sample came through.
mrd::hal::modbus::ModbusCounters run_against(ModbusTestServer::Forge forge, std::uint64_t reads) {
  ModbusTestServer server(std::move(forge));
  EXPECT_TRUE(server.listening());
  MonotonicClock clock;
  ModbusBackend backend(mrd::test::client_config(server.port()), clock);
  EXPECT_TRUE(backend.start().ok);
  EXPECT_TRUE(wait_for([&] { return backend.counters()[ModbusEvent::kReadErrors] >= reads; }));
  EXPECT_FALSE(backend.lvdt().latest().has_value());
  backend.stop();
  return backend.counters();
}

TEST(ModbusBadResponses, OneRegisterWhereTwoWereAskedIsALinkFailureNotASample) {
  const auto c = run_against(
      [](Request q) { return tcp_response(q, {q[kFunction], 2, 0x12, 0x34}); }, 3);
  EXPECT_EQ(c[ModbusEvent::kReadsOk], 0u);
  EXPECT_EQ(c[ModbusEvent::kExceptionResponses], 0u);
  EXPECT_GE(c[ModbusEvent::kDisconnects], 2u);
  EXPECT_GE(c[ModbusEvent::kConnects], 3u);  // reconnected after each
}

TEST(ModbusBadResponses, AResponseCutOffOnTheWireTimesOut) {
  const auto c = run_against(
      [](Request q) {
        auto bytes = tcp_response(q, {q[kFunction], 4, 0x12, 0x34, 0x56, 0x78});
        bytes.resize(bytes.size() - 3);  // the length field promises three more bytes
        return bytes;
      },
      2);
  EXPECT_EQ(c[ModbusEvent::kReadsOk], 0u);
  EXPECT_GE(c[ModbusEvent::kTimeouts], 2u);
  EXPECT_GE(c[ModbusEvent::kDisconnects], 1u);
}

TEST(ModbusBadResponses, AnAnswerToAnotherFunctionCodeIsRefused) {
  const auto c = run_against(
      [](Request q) {
        const auto other = static_cast<std::uint8_t>(q[kFunction] == 0x04 ? 0x03 : 0x04);
        return tcp_response(q, {other, 4, 0x00, 0x00, 0x03, 0xE8});
      },
      3);
  EXPECT_EQ(c[ModbusEvent::kReadsOk], 0u);
  EXPECT_EQ(c[ModbusEvent::kDecodeErrors], 0u);
  EXPECT_GE(c[ModbusEvent::kDisconnects], 2u);
}

TEST(ModbusBadResponses, ExceptionCodesAreCountedAndTheLinkKept) {
  // Illegal data address, server device failure, server busy.
  for (const std::uint8_t code : std::initializer_list<std::uint8_t>{0x02, 0x04, 0x06}) {
    const auto c = run_against(
        [code](Request q) {
          return tcp_response(q, {static_cast<std::uint8_t>(q[kFunction] | 0x80), code});
        },
        3);
    EXPECT_GE(c[ModbusEvent::kExceptionResponses], 3u) << int(code);
    EXPECT_EQ(c[ModbusEvent::kDisconnects], 0u) << int(code);
    EXPECT_EQ(c[ModbusEvent::kConnects], 1u) << int(code);
  }
}

TEST(ModbusBadResponses, AnExceptionCodeNoDeviceSendsIsABadFrame) {
  const auto c = run_against(
      [](Request q) { return tcp_response(q, {static_cast<std::uint8_t>(q[kFunction] | 0x80), 0x55}); },
      3);
  EXPECT_EQ(c[ModbusEvent::kExceptionResponses], 0u);
  EXPECT_GE(c[ModbusEvent::kDisconnects], 2u);
}

}  // namespace
