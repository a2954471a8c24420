#include "cnf/internal/incremental_sat.hpp"

#include <cadical.hpp>

#include <stdexcept>
#include <string>

#include "common/assert.hpp"

namespace gridlock {

// The learner only counts conflicts (CaDiCaL 1.5 has no public counter):
// it is asked about every learned clause and declines to receive it.
struct IncrementalSat::Impl : CaDiCaL::Terminator, CaDiCaL::Learner {
  CaDiCaL::Solver solver;
  const std::function<bool(uint64_t)>* stop = nullptr;
  uint64_t conflicts = 0;
  bool terminate() override { return stop && (*stop)(conflicts); }
  bool learning(int) override {
    ++conflicts;
    return false;
  }
  void learn(int) override {}
};

IncrementalSat::IncrementalSat() : impl_(std::make_unique<Impl>()) {
  impl_->solver.set("quiet", 1);
  impl_->solver.connect_learner(impl_.get());
}

IncrementalSat::~IncrementalSat() { impl_->solver.disconnect_learner(); }

int IncrementalSat::new_var() { return ++vars_; }

void IncrementalSat::add_lits(const int* first, const int* last) {
  for (const int* p = first; p != last; ++p)
    GRIDLOCK_REQUIRE(*p != 0 && *p <= vars_ && -*p <= vars_, "IncrementalSat: literal out of range");
  if (buffered_) {
    pending_.insert(pending_.end(), first, last);
    pending_.push_back(0);
    return;
  }
  for (const int* p = first; p != last; ++p) impl_->solver.add(*p);
  impl_->solver.add(0);
}

void IncrementalSat::flush() {
  if (pending_.empty()) return;
  impl_->solver.reserve(vars_);
  for (const int lit : pending_) impl_->solver.add(lit);
  pending_.clear();
}

void IncrementalSat::set_option(const char* name, int value) {
  if (!CaDiCaL::Solver::is_valid_option(name) || !impl_->solver.set(name, value))
    throw std::invalid_argument(std::string("IncrementalSat: cannot set option ") + name);
}

void IncrementalSat::set_buffered(bool on) {
  flush();
  buffered_ = on;
}

void IncrementalSat::add_clause(const std::vector<int>& lits) { add_lits(lits.data(), lits.data() + lits.size()); }

void IncrementalSat::add_clause(std::initializer_list<int> lits) { add_lits(lits.begin(), lits.end()); }

Verdict IncrementalSat::solve(const std::function<bool(uint64_t)>& stop) {
  flush();
  if (vars_ > 0) impl_->solver.reserve(vars_);
  impl_->stop = &stop;
  impl_->solver.connect_terminator(impl_.get());
  const int code = impl_->solver.solve();
  impl_->solver.disconnect_terminator();
  impl_->stop = nullptr;
  return code == 10 ? Verdict::Yes : code == 20 ? Verdict::No : Verdict::Unknown;
}

void IncrementalSat::set_phase(int lit) {
  flush();
  impl_->solver.phase(lit);
}

bool IncrementalSat::value(int var) const { return impl_->solver.val(var) > 0; }

uint64_t IncrementalSat::conflicts() const { return impl_->conflicts; }

void IncrementalSat::trace_proof(std::FILE* file) {
  if (!pending_.empty()) throw std::logic_error("IncrementalSat: cannot trace a proof now");
  impl_->solver.set("binary", 0);
  impl_->solver.set("elim", 0);
  if (!impl_->solver.trace_proof(file, "<proof>")) throw std::logic_error("IncrementalSat: cannot trace a proof now");
}

void IncrementalSat::flush_proof() { impl_->solver.flush_proof_trace(); }

}  // namespace gridlock
