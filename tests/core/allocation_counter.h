#pragma once
// Counts what the program allocates through global operator new (allocation_counter.cpp
// replaces it for the whole core test program; it only counts, so other tests are unaffected).
#include <cstdint>

namespace ydscope::test {

struct AllocationTally {
  std::uint64_t calls = 0;
  std::uint64_t bytes = 0;
  std::uint64_t largest = 0;  // the largest single allocation
};

// Everything allocated since the program started (largest: since the last reset_largest()).
AllocationTally allocations();
void reset_largest_allocation();

}  // namespace ydscope::test
