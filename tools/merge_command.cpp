// gridlock merge: combine the JSON results of the shards of one fuzz, verify
// or gen-instances run (--shard K/N --json-out F) into the report the
// unsharded run gives (docs/verify.md, "Campaigns beyond one machine").
#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "common/internal/atomic_file.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

using nlohmann::json;

struct ShardFile {
  std::string path;
  json j;
  uint64_t k = 0, n = 1;
};

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw UserError(Diagnostic{path, 0, what}); }

ShardFile load(const std::string& path) {
  protect_input(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot read file");
  std::stringstream ss;
  ss << in.rdbuf();
  ShardFile f;
  f.path = path;
  f.j = json::parse(ss.str(), nullptr, false);
  if (f.j.is_discarded() || !f.j.is_object()) fail(path, "not a JSON object (want the file of --json-out)");
  if (!f.j.contains("shard") || !f.j["shard"].is_string())
    fail(path, "no \"shard\" field (want the file of --json-out)");
  // An interrupted shard holds only part of its formulas: merging it would
  // pass for a complete run.
  if (f.j.value("interrupted", false)) fail(path, "this shard was interrupted: run it again before merging");
  const std::string s = f.j["shard"].get<std::string>();
  try {
    cli::parse_shard(s, f.k, f.n);
  } catch (const UserError&) {
    fail(path, "bad \"shard\" field '" + s + "'");
  }
  return f;
}

std::string kind_of(const ShardFile& f) {
  if (f.j.contains("command") && f.j["command"].is_string()) return f.j["command"].get<std::string>();
  if (f.j.value("generator", "") == "gridlock gen-instances") return "gen-instances";
  fail(f.path, "neither a fuzz, verify nor gen-instances result");
}

// Every shard of 0..N-1 exactly once, and the fields that define the run equal.
void check_complete(const std::vector<ShardFile>& files, const std::vector<std::string>& same) {
  const uint64_t n = files[0].n;
  std::set<uint64_t> seen;
  for (const auto& f : files) {
    if (f.n != files[0].n)
      fail(f.path, "shard " + f.j["shard"].get<std::string>() + " is of another split than " + files[0].path + " (" +
                       files[0].j["shard"].get<std::string>() + ")");
    if (!seen.insert(f.k).second)
      fail(f.path, "shard " + std::to_string(f.k) + "/" + std::to_string(n) + " given twice");
    for (const auto& key : same)
      if (f.j.value(key, json()) != files[0].j.value(key, json()))
        fail(f.path, "\"" + key + "\" differs from " + files[0].path + ": shards of different runs");
  }
  for (uint64_t k = 0; k < n; ++k)
    if (!seen.count(k)) throw UserError("merge: shard " + std::to_string(k) + "/" + std::to_string(n) + " is missing");
}

uint64_t sum(const std::vector<ShardFile>& files, const std::string& key) {
  uint64_t s = 0;
  for (const auto& f : files) s += f.j.value(key, uint64_t{0});
  return s;
}

json merge_fuzz(const std::vector<ShardFile>& files) {
  check_complete(files, {"seed", "campaign"});
  json out = files[0].j;
  out["shard"] = "0/1";
  double seconds = 0;
  json findings = json::array();
  for (const auto& f : files) {
    seconds = std::max(seconds, f.j.value("seconds", 0.0));
    for (const auto& x : f.j["findings"]) findings.push_back(x);
  }
  std::sort(findings.begin(), findings.end(),
            [](const json& a, const json& b) { return a["index"].get<uint64_t>() < b["index"].get<uint64_t>(); });
  for (const char* key :
       {"formulas", "sat", "unsat", "unknown", "certificates_checked", "no_certificates_checked", "disagreements"})
    out[key] = sum(files, key);
  out["seconds"] = seconds;  // wall clock of shards run side by side
  out["findings"] = findings;
  out["status"] = out["disagreements"].get<uint64_t>() ? "DISAGREE" : "AGREE";
  return out;
}

json merge_verify(const std::vector<ShardFile>& files) {
  check_complete(files, {"inputs", "model", "run_id"});
  json out = files[0].j;
  out["shard"] = "0/1";
  json rows = json::array();
  for (const auto& f : files)
    for (const auto& r : f.j["formulas"]) rows.push_back(r);
  std::sort(rows.begin(), rows.end(),
            [](const json& a, const json& b) { return a["index"].get<uint64_t>() < b["index"].get<uint64_t>(); });
  const uint64_t inputs = files[0].j.value("inputs", uint64_t{0});
  if (rows.size() != inputs)
    throw UserError("merge: the shards hold " + std::to_string(rows.size()) + " formulas, the run has " +
                    std::to_string(inputs));
  // Each input exactly once (shards of one run split the list; a row of
  // another list would show one formula twice and drop another).
  for (size_t i = 0; i < rows.size(); ++i)
    if (!rows[i].contains("index") || rows[i]["index"] != i)
      throw UserError("merge: formula " + std::to_string(i) + " is missing or given twice in the shards");
  out["formulas"] = rows;
  json summary = json::object();
  for (const auto& [key, v] : files[0].j["summary"].items()) {
    uint64_t s = 0;
    for (const auto& f : files) s += f.j["summary"].value(key, uint64_t{0});
    summary[key] = s;
  }
  out["summary"] = summary;
  out["exit_code"] = summary.value("disagree", uint64_t{0}) ? 1 : 0;
  return out;
}

json merge_instances(const std::vector<ShardFile>& files) {
  check_complete(files, {"generator", "problem", "seed", "vars", "planned", "run_id"});
  json out = files[0].j;
  out["shard"] = "0/1";
  json entries = json::array();
  for (const auto& f : files)
    for (const auto& e : f.j["instances"]) entries.push_back(e);
  // With --model both, an index has two entries (discrete, then continuous):
  // the stable sort keeps each shard's order of them.
  std::stable_sort(entries.begin(), entries.end(), [](const json& a, const json& b) {
    return a["index"].get<uint64_t>() < b["index"].get<uint64_t>();
  });
  out["yes"] = sum(files, "yes");
  out["no"] = sum(files, "no");
  out["skipped"] = sum(files, "skipped");
  out["instances"] = entries;
  return out;
}

int run_merge(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("out,o", po::value<std::string>()->default_value("-"),
                                                 "write the combined JSON here (default: standard output)");
  po::options_description hidden;
  hidden.add_options()("inputs", po::value<std::vector<std::string>>()->required(), "shard results");
  po::positional_options_description pos;
  pos.add("inputs", -1);
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "merge SHARD.json... [-o OUT.json]",
                       "Combines the --json-out files of the shards (--shard K/N, K = 0..N-1, each exactly once)\n"
                       "of one 'gridlock fuzz', 'gridlock verify' or 'gridlock gen-instances' run into the JSON the\n"
                       "unsharded run gives: counts summed, findings / rows / instances in the unsharded order;\n"
                       "only the times differ (fuzz: seconds is the longest shard's). A summary goes to stderr.\n"
                       "Exit as the unsharded run would: fuzz and verify 1 if anything disagreed, else 0.",
                       &hidden))
    return 0;
  std::vector<ShardFile> files;
  for (const auto& p : vm["inputs"].as<std::vector<std::string>>()) files.push_back(load(p));
  const std::string kind = kind_of(files[0]);
  for (const auto& f : files)
    if (kind_of(f) != kind) fail(f.path, "a " + kind_of(f) + " result among " + kind + " results");
  json out;
  std::string summary;
  int code = 0;
  if (kind == "fuzz") {
    out = merge_fuzz(files);
    code = out["disagreements"].get<uint64_t>() ? 1 : 0;
    summary = std::to_string(out["formulas"].get<uint64_t>()) + " formulas, " +
              std::to_string(out["disagreements"].get<uint64_t>()) +
              " disagreements: " + out["status"].get<std::string>();
  } else if (kind == "verify") {
    out = merge_verify(files);
    code = out["exit_code"].get<int>();
    summary = std::to_string(out["summary"]["formulas"].get<uint64_t>()) + " formulas, " +
              std::to_string(out["summary"]["agree"].get<uint64_t>()) + " agree, " +
              std::to_string(out["summary"]["unknown"].get<uint64_t>()) + " unknown, " +
              std::to_string(out["summary"]["disagree"].get<uint64_t>()) + " disagree";
  } else if (kind == "gen-instances") {
    out = merge_instances(files);
    summary = std::to_string(out["instances"].size()) + " instances (" + std::to_string(out["yes"].get<int64_t>()) +
              " YES, " + std::to_string(out["no"].get<int64_t>()) + " NO)";
  } else {
    fail(files[0].path, "cannot merge results of '" + kind + "'");
  }
  const std::string dest = vm["out"].as<std::string>();
  cli::write_text_file(dest, (kind == "gen-instances" ? out.dump(2) : out.dump()) + "\n");
  std::cerr << "c merged " << files.size() << " " << kind << " shards: " << summary << "\n";
  return code;
}

Command reg{"merge", "combine the --json-out results of sharded fuzz / verify / gen-instances runs", run_merge};

}  // namespace
}  // namespace gridlock
