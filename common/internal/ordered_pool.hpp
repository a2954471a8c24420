// Parallel work with results taken in order: the engine behind `--jobs N`
// of fuzz, verify and gen-instances (docs/verify.md).
//
// run_in_order(jobs, count, work, take, before) computes work(i, w) for
// i = 0, 1, ..., count - 1 on `jobs` threads (w: the worker, 0 <= w < jobs)
// and hands each result to take(i, result) on the calling thread, strictly in
// index order. Everything a campaign prints, writes or counts happens in
// take, so its output is the same for every number of workers: the workers
// share nothing mutable but this queue, and each owns the state its w
// selects (one Verifier, one CaDiCaL per worker).
//
// The run ends, at the first of:
//  - every item taken;
//  - take returns false (a campaign that stops at its first disagreement);
//  - work returns std::nullopt (a time limit, or an answer a stop request
//    may have cut short: this item and the later ones are not taken);
//  - a stop request (stop_requested(), SIGINT/SIGTERM) while take waits for
//    an item not finished yet. Items finished before are still taken in
//    order: work must return nullopt for an item a stop may have cut short.
//    With jobs <= 1 the stop request is polled before each item.
// Workers run at most `window` (4 * jobs) items ahead of take, so memory
// stays bounded; items beyond the end may have been computed and are thrown
// away. An exception thrown by work(i) is rethrown by run_in_order when item
// i's turn comes (not before: earlier items are taken first); one thrown by
// take or before ends the run. Either way, all workers are joined before
// run_in_order returns or throws (each finishes its item in progress).
// before(i), if given, is called on the calling thread before it waits for
// item i (a progress line naming the item in progress).
// jobs <= 1 runs everything on the calling thread, with no thread made.
#pragma once

#include <sched.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/limits.hpp"

namespace gridlock {

// The cores this process may run on (its CPU affinity), at least 1: the
// default of --jobs.
inline unsigned available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return static_cast<unsigned>(CPU_COUNT(&set));
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? n : 1;
}

namespace detail {

// The queue the workers and the taker share; everything under mutex_.
template <class R>
class OrderedQueue {
 public:
  explicit OrderedQueue(uint64_t count, uint64_t window) : count_(count), window_(window), slots_(window) {}

  // The next index for a worker, or nullopt when the run is over for it.
  std::optional<uint64_t> next() {
    std::unique_lock<std::mutex> lock(mutex_);
    worker_cv_.wait(lock, [&] { return end_ || next_ >= count_ || next_ < taken_ + window_; });
    if (end_ || next_ >= count_) return std::nullopt;
    return next_++;
  }

  // Stores item i's result (or error); a nullopt result ends the handing out.
  void put(uint64_t i, std::optional<R> value, const std::exception_ptr& error) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      Slot& s = slots_[i % window_];
      s.value = std::move(value);
      s.error = error;
      s.ready = true;
      if (!s.value && !s.error) end_ = true;
    }
    taker_cv_.notify_one();
  }

  // Waits for item i (polling the stop request, which a signal handler
  // cannot notify); false on a stop request before it is ready.
  bool wait(uint64_t i, std::optional<R>& value, std::exception_ptr& error) {
    std::unique_lock<std::mutex> lock(mutex_);
    Slot& s = slots_[i % window_];
    while (!s.ready) {
      if (stop_requested()) return false;
      taker_cv_.wait_for(lock, std::chrono::milliseconds(20));
    }
    value = std::move(s.value);
    error = std::move(s.error);
    s = Slot{};
    taken_ = i + 1;
    lock.unlock();
    worker_cv_.notify_all();
    return true;
  }

  // No more items for the workers.
  void finish() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      end_ = true;
    }
    worker_cv_.notify_all();
  }

 private:
  struct Slot {
    bool ready = false;
    std::optional<R> value;
    std::exception_ptr error;
  };
  const uint64_t count_, window_;
  std::mutex mutex_;
  std::condition_variable worker_cv_, taker_cv_;
  std::vector<Slot> slots_;
  uint64_t next_ = 0, taken_ = 0;
  bool end_ = false;
};

}  // namespace detail

template <class Work, class Take>
void run_in_order(unsigned jobs, uint64_t count, Work&& work, Take&& take,
                  const std::function<void(uint64_t)>& before = {}) {
  using R = typename std::invoke_result_t<Work&, uint64_t, unsigned>::value_type;
  if (jobs <= 1) {
    for (uint64_t i = 0; i < count && !stop_requested(); ++i) {
      if (before) before(i);
      std::optional<R> r = work(i, 0u);
      if (!r || !take(i, *r)) return;
    }
    return;
  }
  detail::OrderedQueue<R> queue(count, 4 * uint64_t{jobs});
  std::vector<std::thread> workers;
  // Joins the workers however the run ends (a return, take's exception).
  struct Joiner {
    detail::OrderedQueue<R>& q;
    std::vector<std::thread>& threads;
    ~Joiner() {
      q.finish();
      for (auto& t : threads) t.join();
    }
  } joiner{queue, workers};
  for (unsigned w = 0; w < jobs; ++w)
    workers.emplace_back([&queue, &work, w] {
      while (std::optional<uint64_t> i = queue.next()) {
        std::optional<R> value;
        std::exception_ptr error;
        try {
          value = work(*i, w);
        } catch (...) {
          error = std::current_exception();
        }
        queue.put(*i, std::move(value), error);
      }
    });
  for (uint64_t i = 0; i < count; ++i) {
    if (before) before(i);
    std::optional<R> value;
    std::exception_ptr error;
    if (!queue.wait(i, value, error)) return;
    if (error) std::rethrow_exception(error);
    if (!value || !take(i, *value)) return;
  }
}

}  // namespace gridlock
