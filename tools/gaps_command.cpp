// gridlock gaps: continuous Collision-free Schedule for horizontal-only
// instances, in linear time (run everything at once; paper's theorem).
#include "lattice/geometry.hpp"
#include "solver/gaps.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

int run_gaps(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("json", "print one JSON object instead of c/s/v lines");
  po::variables_map vm;
  if (!cli::parse_args_one_input(args, opts, "instance", vm, "gaps INSTANCE.grid [--json]",
                                 "Continuous Collision-free Schedule for a horizontal-only instance, in linear time:\n"
                                 "a collision-free schedule exists iff starting every coupling at time 0 is one.\n"
                                 "s YES (exit 10) with that schedule as 'v NAME 0' lines ('gridlock check --times'\n"
                                 "reads them back), or s NO (exit 20) naming the gap that closes (row, end nodes,\n"
                                 "initial size, the operations that widen and narrow it) or the cycle that opens."))
    return 0;
  const std::string path = vm["instance"].as<std::string>();
  Instance inst = cli::load_instance(path);
  cli::Activity act(path, "checking the gaps");  // out of memory names the file
  if (!inst.horizontal_only()) {
    for (const Operation& op : inst.ops())
      if (!is_horizontal(op.dir))
        throw UserError(path + ": operation '" + op.name + "' moves vertically (" + dir_name(op.dir) +
                        "); gaps decides horizontal-only instances (use 'gridlock solve' for the discrete model)");
  }
  Answer ans("gaps", vm.count("json") > 0);
  ans.witness_one_per_line();
  ans.comment("gridlock gaps " + path + ": " + std::to_string(inst.num_nodes()) + " nodes, " +
              std::to_string(inst.ops().size()) + " operations, " + std::to_string(inst.couplings().size()) +
              " couplings");
  GapVerdict v = check_gaps(inst);
  ans.comment("checked " + std::to_string(v.gaps_checked) + " gaps (" + std::to_string(v.negative_gaps) +
              " close) and " + std::to_string(v.cycles_checked) + " cycles (" + std::to_string(v.open_cycles) +
              " open)");
  ans.comment(describe_gap_verdict(inst, v));
  nlohmann::json& d = ans.data();
  d["gaps_checked"] = v.gaps_checked;
  d["negative_gaps"] = v.negative_gaps;
  d["cycles_checked"] = v.cycles_checked;
  d["open_cycles"] = v.open_cycles;
  if (v.collision_free) {
    ans.comment("witness: every coupling starts at time 0");
    for (const Coupling& q : inst.couplings()) ans.witness(q.name + " 0");
    return ans.finish(Verdict::Yes);
  }
  if (v.reason == GapVerdict::Reason::Gap) {
    nlohmann::json g;
    g["row"] = v.row;
    g["left"] = inst.node_label(v.left);
    g["right"] = inst.node_label(v.right);
    g["initial_size"] = v.initial_size;
    g["final_size"] = v.final_size;
    for (const GapChange& c : v.changes)
      (c.delta > 0 ? g["widened_by"] : g["narrowed_by"]).push_back({{"op", inst.ops()[c.op].name}, {"delta", c.delta}});
    d["gap"] = g;
  } else {
    nlohmann::json cy;
    for (NodeId w : v.cycle) cy["nodes"].push_back(inst.node_label(w));
    cy["mismatch"] = v.mismatch;
    d["cycle"] = cy;
  }
  return ans.finish(Verdict::No);
}

Command reg{"gaps", "decide continuous Collision-free Schedule for horizontal-only instances (linear time)", run_gaps};

}  // namespace
}  // namespace gridlock
