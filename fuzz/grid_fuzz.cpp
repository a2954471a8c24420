// libFuzzer target: the .grid reader, then the simulator on what it accepts.
// Any input must give either a Diagnostic or a valid instance; never a crash,
// a sanitizer report, or an exception. Accepted small instances are also run
// through the simulator with the order of their couplings, and the writer's
// output must read back to the same text.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  gridlock::Instance inst;
  if (gridlock::read_instance(in, "fuzz.grid", inst)) return 0;
  std::ostringstream once;
  gridlock::write_instance(once, inst);
  gridlock::Instance back;
  std::istringstream again(once.str());
  if (gridlock::read_instance(again, "again.grid", back)) __builtin_trap();
  std::ostringstream twice;
  gridlock::write_instance(twice, back);
  if (twice.str() != once.str()) __builtin_trap();
  if (inst.num_nodes() <= 64 && inst.couplings().size() <= 16) {
    std::vector<gridlock::CouplingId> order;
    for (gridlock::CouplingId q = 0; q < inst.couplings().size(); ++q) order.push_back(q);
    gridlock::Simulator sim(inst);
    (void)sim.run_order(order);
  }
  return 0;
}
