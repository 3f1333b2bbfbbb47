// The one boundary between PatchLab and OpenCASCADE (this header includes OCCT). OCCT reports
// failures by throwing Standard_Failure and its subclasses (Standard_ConstructionError,
// Standard_OutOfRange, ...), which are not std::exceptions: one escaping the export ended the
// process by SIGABRT. Every call into OCCT, on the way out (the STEP/IGES writers, the faces,
// the sewing) and on the way in (the readers), runs inside occt_call, which turns whatever it
// throws into the project's located error: DataError(file, object, "what failed: why").
//
// OCCT's long operations (the sewing, the translators) poll a progress indicator for a user
// break; CadDeadline's indicator asks them to stop once the deadline has passed, and
// occt_call_until says so by name, so a shape that would keep OCCT busy ends in a message.
#pragma once

#include <Message_ProgressIndicator.hxx>
#include <Standard_Failure.hxx>
#include <chrono>
#include <new>
#include <string>
#include <type_traits>
#include <utility>

#include "core/base/data_error.hpp"
#include "core/io/json_node.hpp"  // short_number

namespace pl {

// Where a failure is reported: the file (the scene, or the CAD file read) and the object being
// worked on (a face, a curve, "" for the whole shape).
struct CadPlace {
  std::string file;
  std::string object;
};

// A wall-clock deadline for the work of one export or import (steady clock). seconds <= 0 or
// infinite: none.
class CadDeadline {
 public:
  explicit CadDeadline(double seconds = 0);
  bool passed() const;
  double seconds() const { return seconds_; }
  // The progress indicator to hand to OCCT's operations (sewing, translators): it asks them to
  // stop once the deadline has passed. Its Start() is to be called by the caller.
  Handle(Message_ProgressIndicator) indicator() const;

 private:
  double seconds_;
  std::chrono::steady_clock::time_point end_;
};

// "Standard_ConstructionError: <OCCT's message>" (the class name says what kind of failure).
std::string occt_failure_text(const Standard_Failure& f);

// Runs body(); a DataError passes through, anything else thrown becomes
// DataError(place.file, place.object, action + ": " + reason).
template <class F>
decltype(auto) occt_call(const CadPlace& place, const std::string& action, F&& body) {
  try {
    return std::forward<F>(body)();
  } catch (const DataError&) {
    throw;
  } catch (const Standard_Failure& f) {
    throw DataError(place.file, place.object, action + ": " + occt_failure_text(f));
  } catch (const std::bad_alloc&) {
    throw DataError(place.file, place.object, action + ": out of memory");
  } catch (const std::exception& e) {
    throw DataError(place.file, place.object, action + ": " + e.what());
  }
}

// occt_call for an operation given deadline.indicator(): if it returned because the deadline
// passed (OCCT stops quietly on a user break), that is the error.
template <class F>
decltype(auto) occt_call_until(const CadPlace& place, const std::string& action,
                               const CadDeadline& deadline, F&& body) {
  auto check = [&] {
    if (deadline.passed())
      throw DataError(
          place.file, place.object,
          action + ": stopped at the time limit of " + short_number(deadline.seconds()) + " s");
  };
  check();
  if constexpr (std::is_void_v<decltype(body())>) {
    occt_call(place, action, std::forward<F>(body));
    check();
  } else {
    auto r = occt_call(place, action, std::forward<F>(body));
    check();
    return r;
  }
}

}  // namespace pl
