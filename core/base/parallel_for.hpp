// The core's parallel loops: oneTBB's work-stealing scheduler over tasks of `grain` iterations.
//
// Why not a static split (one slice per thread, then a barrier): on a desktop the cores are never
// free, and a thread the kernel has descheduled would hold its whole slice, so a 1 ms update
// waited out a scheduler slice (8 ms measured with one core busy). Here a loop is cut into many
// more tasks than threads and whichever thread is running takes the next one; a descheduled
// thread holds at most one small task. Idle workers sleep instead of spinning for long, so they
// do not take the core from the renderer either.
//
// Every iteration must compute its results independently of how the range is cut: the results
// are then the same bit for bit on any number of threads (tests/core/parallel_determinism_test).
#pragma once

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>

#include <cstddef>
#include <exception>
#include <vector>

namespace pl {

// Calls body(begin, end) over [0, n) in tasks of at most `grain` iterations (at least grain / 2
// when n allows), on whichever threads are running; the first exception a task throws is rethrown
// here once the others have stopped. A range of at most `grain` runs on the calling thread.
template <class Body>
void parallel_chunks(std::size_t n, std::size_t grain, Body&& body) {
  if (grain == 0) grain = 1;
  if (n <= grain) {
    if (n > 0) body(std::size_t(0), n);
    return;
  }
  // simple_partitioner: tasks of the grain we measured, not the few large ones auto_partitioner
  // starts with (one of which a descheduled thread would hold).
  oneapi::tbb::parallel_for(
      oneapi::tbb::blocked_range<std::size_t>(0, n, grain),
      [&](const oneapi::tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); },
      oneapi::tbb::simple_partitioner());
}

// body(i) for every i in [0, n), `grain` indices a task, as parallel_chunks runs them. Every
// index runs even when some throw; then the exception of the lowest index is rethrown, so the
// message a caller reports (the first bad face of a scene) is the same on any number of threads.
template <class Body>
void parallel_each(std::size_t n, std::size_t grain, Body&& body) {
  std::vector<std::exception_ptr> errors(n);
  parallel_chunks(n, grain, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      try {
        body(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace pl
