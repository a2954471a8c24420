// Command-line plumbing the campaign commands (fuzz, verify, gen-instances)
// share: --shard, --jobs, --model/--direct/--break-gadget, the progress line on a
// terminal, --json-out, and the "interrupted" note. The campaigns themselves
// are library code (verify/campaign.hpp, verify/instance_set.hpp).
#pragma once

#include <string>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include "tools/progress_line.hpp"
#include "tools/user_error.hpp"
#include "verify/campaign.hpp"

namespace gridlock::cli {

// vm["shard"] ("K/N", 0 <= K < N) or UserError.
Shard shard_arg(const boost::program_options::variables_map& vm);

// Adds --jobs N (worker threads; default: the cores available) to opts.
void add_jobs_option(boost::program_options::options_description& opts);
// vm["jobs"] (1 to 1024), or the cores available (common/internal/ordered_pool.hpp
// available_cores) when not given; UserError when out of range.
unsigned jobs_arg(const boost::program_options::variables_map& vm);

// vm["model"], vm["direct"] and vm["break-gadget"] into opt (UserError for
// an unknown model or mutation).
void verify_model_args(const boost::program_options::variables_map& vm, VerifyOptions& opt);

// Writes j (indented) to vm["json-out"] when that option is given.
void write_json_out(const boost::program_options::variables_map& vm, const nlohmann::json& j);

// "INTERRUPTED by signal S" for the signal that stopped the campaign.
std::string interrupted_note();

}  // namespace gridlock::cli
