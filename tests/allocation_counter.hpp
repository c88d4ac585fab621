// SPDX-License-Identifier: MIT
#pragma once
// For tests that prove a function never allocates: link tests/allocation_counter.cpp into the
// test program (it replaces the global operator new/delete with counting ones) and compare
// allocation_count() before and after.

namespace tutti::test {

// Calls of any global operator new so far in this program.
long allocation_count();

}  // namespace tutti::test
