// libFuzzer target: the NO-certificate checker (certify/) on any text, for
// one fixed instance (fuzz/certificate_instance.grid: a 2-variable UNSAT
// formula compiled for continuous time, so that the seed certificates'
// coupling digest matches and the fuzzer reaches every line kind), checked
// as discrete and as continuous. Any input must give a verdict with a
// reason or a proof; never a crash, a sanitizer report, or an exception.
// An accepted certificate must really be one: the instance is NO in both
// models, so acceptance itself is no bug, but a reason must be empty then.
// A collide certificate (no schedule collides) must never be accepted: some
// schedule of this instance collides ('gridlock collide' says YES).
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "certify/certify.hpp"
#include "lattice/grid_format.hpp"

namespace {

const gridlock::Instance& fuzz_instance() {
  static const gridlock::Instance inst = [] {
    // Beside this source file (the fuzz targets run from a source tree).
    const std::string here = __FILE__;
    const std::string path = here.substr(0, here.rfind('/') + 1) + "certificate_instance.grid";
    std::ifstream in(path);
    gridlock::Instance i;
    if (!in || gridlock::read_instance(in, path, i)) __builtin_trap();
    return i;
  }();
  return inst;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* model : {"discrete", "continuous"}) {
    const gridlock::CertifyResult r = gridlock::certify(fuzz_instance(), text, model);
    if (r.proved != r.reason.empty()) __builtin_trap();
    if (r.proved && r.kind == "collide") __builtin_trap();
  }
  return 0;
}
