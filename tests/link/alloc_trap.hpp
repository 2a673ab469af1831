// The allocation trap: the test binary that links alloc_trap.cpp replaces the
// global operator new and counts its calls on the calling thread while
// counting is on. Other threads (a board's server, the journal writer, a
// sink's drain) are not real-time and are not counted.
#pragma once

namespace kerf::test {

// Starts counting on this thread from zero; the count so far stays readable.
void alloc_trap_start();
void alloc_trap_pause();
void alloc_trap_resume();
void alloc_trap_stop();
long alloc_trap_count();

}  // namespace kerf::test
