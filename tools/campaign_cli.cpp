#include "tools/campaign_cli.hpp"

#include <iostream>

#include "common/diagnostic.hpp"
#include "common/internal/ordered_pool.hpp"
#include "common/limits.hpp"
#include "tools/cli_common.hpp"
#include "tools/options.hpp"
#include "tools/user_error.hpp"

namespace gridlock::cli {

Shard shard_arg(const boost::program_options::variables_map& vm) {
  Shard s;
  parse_shard(vm["shard"].as<std::string>(), s.k, s.n);
  return s;
}

void add_jobs_option(boost::program_options::options_description& opts) {
  opts.add_options()("jobs,j", boost::program_options::value<std::string>(),
                     "worker threads (default: the cores available); the output is the same for every number");
}

unsigned jobs_arg(const boost::program_options::variables_map& vm) {
  if (!vm.count("jobs")) return available_cores();
  return static_cast<unsigned>(int_arg(vm, "jobs", 1, 1024));
}

void verify_model_args(const boost::program_options::variables_map& vm, VerifyOptions& opt) {
  const auto& gadget = vm["break-gadget"].as<std::string>();
  auto mutation = parse_mutation(gadget);
  if (!mutation) throw UserError("unknown --break-gadget '" + gadget + "'");
  opt.mutation = *mutation;
  const auto& model_name = vm["model"].as<std::string>();
  auto model = TimeModels::parse(model_name);
  if (!model) throw UserError("--model must be discrete, continuous or both, not '" + model_name + "'");
  opt.models = *model;
  opt.direct = vm.count("direct") > 0;
  opt.certify = vm.count("no-certificates") == 0;
}

void write_json_out(const boost::program_options::variables_map& vm, const nlohmann::json& j) {
  if (vm.count("json-out")) write_text_file(vm["json-out"].as<std::string>(), j.dump(2) + "\n");
}

std::string interrupted_note() { return "INTERRUPTED by signal " + std::to_string(stop_signal().load()); }

}  // namespace gridlock::cli
