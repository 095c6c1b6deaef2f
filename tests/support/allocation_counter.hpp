#pragma once

#include <cstdint>

namespace mrd::test {

// Counts heap allocations (operator new and malloc/calloc/realloc) made while counting is on,
// in any thread of the process. Link mrd_alloc_counter into the test binary to activate it.
void start_counting_allocations();
std::uint64_t stop_counting_allocations();  // returns the count since start

}  // namespace mrd::test
