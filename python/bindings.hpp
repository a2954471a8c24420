// What the Python module's binding files share (docs/python.md): errors as
// gridlock.Error, exact values as int and fractions.Fraction, schedules
// given by coupling names, and long calls that release the GIL and stop on
// Ctrl-C.
#pragma once

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <condition_variable>
#include <csignal>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/diagnostic.hpp"
#include "common/limits.hpp"
#include "lattice/instance.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"

namespace gridlock::python {

namespace py = pybind11;

// Bad input, raised in Python as gridlock.Error (attributes file, line,
// message; str() is "FILE:LINE: message", as the command line prints it).
struct InputError : std::runtime_error {
  Diagnostic diagnostic;
  explicit InputError(Diagnostic d) : std::runtime_error(d.str()), diagnostic(std::move(d)) {}
};
[[noreturn]] inline void raise(const Diagnostic& d) { throw InputError(d); }
[[noreturn]] inline void raise(const std::string& message) { throw InputError(Diagnostic{"", 0, message}); }
inline void check(const MaybeError& e) {
  if (e) raise(*e);
}

// Registers gridlock.Error and the translations of InputError and
// std::invalid_argument (the libraries' "bad argument") into it.
void register_errors(py::module_& m);

// fractions.Fraction(num, den) for r.
py::object fraction(const Rational& r);
// An exact value from an int, a fractions.Fraction or a string "a/b";
// anything else (a float above all) raises gridlock.Error.
Rational to_rational(py::handle v);

// Coupling names in this order; start times by coupling name.
py::list order_names(const Instance& inst, const std::vector<CouplingId>& order);
py::dict times_dict(const Instance& inst, const Schedule& s);
// The schedule a call names: exactly one of order (coupling names) and
// times ({name: time}) must be given; checked like the command line's
// --order and --times (every coupling once, bounds).
Schedule schedule_arg(const Instance& inst, const py::object& order, const py::object& times);

// The record of a collision, as `gridlock check --json` writes it, with the
// time as a Fraction: {"kind", "time", "regions" | "cycle", "moving"}.
py::dict collision_dict(const Instance& inst, const Regions& regions, const Collision& c);

// An assignment as DIMACS literals ([1, -2, 3]: variable 1 true, 2 false, 3
// true; variables not named are false) to a vector indexed 1..num_vars, and
// back (every variable once).
std::vector<bool> assignment_arg(const py::handle& literals, int num_vars);
py::list literals_list(const std::vector<bool>& value, int num_vars);

// Runs work() with the GIL released on a worker thread while the calling
// thread polls Python's signal handlers every 50 ms. When a handler raises
// (Ctrl-C: KeyboardInterrupt), the process-wide stop request of
// common/limits.hpp is set, so every loop that polls it (the discrete
// solver's budget, CaDiCaL's terminator, the campaigns) ends soon; the
// request is cleared and the handler's exception re-raised once work()
// returns. work() may take the GIL itself (progress callbacks). Work that
// polls no stop request (the continuous solver's Z3 calls) runs to its own
// limit before the exception is raised.
template <class Work>
auto run_interruptible(Work&& work) -> decltype(work()) {
  using Result = decltype(work());
  std::optional<Result> result;
  std::exception_ptr failure;
  bool done = false, interrupted = false;
  std::mutex mutex;
  std::condition_variable finished;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work());
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      if (interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) interrupted = true;  // the exception stays set in this thread
      }
      if (interrupted) stop_signal().store(SIGINT);
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) {
    stop_signal().store(0);
    throw py::error_already_set();
  }
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

void bind_lattice(py::module_& m);
void bind_solver(py::module_& m);
void bind_cnf(py::module_& m);
void bind_verify(py::module_& m);

}  // namespace gridlock::python
