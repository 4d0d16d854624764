// Counting heap allocations in a test program (issue 12 item 4, issue 14 item 3): the global
// operator new is replaced (std::vector, std::string, ...) and the C allocator's entry points are
// interposed (Eigen's dynamic matrices call std::malloc directly, not operator new), forwarding
// to glibc's __libc_* functions. Link allocation_counter.cpp into the test program (its own
// executable: the counters see everything linked into it).
#pragma once

namespace ssimarch::testing {

/// Whether allocations are counted (not under AddressSanitizer, which replaces the allocator).
bool counting_allocations();
/// Allocations so far (malloc, calloc, realloc, aligned allocations, operator new).
long allocation_count();

/// Allocations made by f().
template <class F>
long allocations_of(F&& f) {
  const long before = allocation_count();
  f();
  return allocation_count() - before;
}

}  // namespace ssimarch::testing
