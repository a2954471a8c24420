// gridlock certify: checks a NO certificate with the independent checker
// (certify/certify.hpp, docs/certificates.md).
#include <fstream>
#include <sstream>

#include "certify/certify.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

const char* const kCertifyDescription =
    "Checks a NO certificate (written by 'gridlock solve --certificate C', or by 'gridlock collide\n"
    "--certificate C': no schedule collides) without the solvers:\n"
    "the checker re-derives the gap inequalities, displacements and region forms from the\n"
    "instance, checks the reason of every clause (in continuous time with exact rationals) and\n"
    "every lemma by unit propagation (docs/certificates.md). s NO (exit 20) and\n"
    "'c certificate checked' when it proves that no collision-free schedule exists; an error\n"
    "(exit 1) naming the line and what failed when it does not.";

int run_certify(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("model", po::value<std::string>()->default_value("discrete"),
                                                 "discrete or continuous: the model the certificate is for")(
      "json", "print one JSON object instead of c/s lines");
  po::options_description hidden;
  hidden.add_options()("instance", po::value<std::string>()->required(), "instance")(
      "certificate", po::value<std::string>()->required(), "certificate");
  po::positional_options_description pos;
  pos.add("instance", 1).add("certificate", 1);
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "certify INSTANCE.grid CERTIFICATE [--model discrete|continuous] [--json]",
                       kCertifyDescription, &hidden))
    return 0;
  const std::string model = vm["model"].as<std::string>();
  if (model != "discrete" && model != "continuous")
    throw UserError("--model must be discrete or continuous, not '" + model + "'");
  const std::string path = vm["instance"].as<std::string>(), cert_path = vm["certificate"].as<std::string>();
  const Instance inst = cli::load_instance(path);
  cli::Activity act(path, "checking the certificate");  // out of memory names the file
  std::ifstream in(cert_path, std::ios::binary);
  if (!in) throw UserError(Diagnostic{cert_path, 0, "cannot read file"});
  std::stringstream text;
  text << in.rdbuf();
  const CertifyResult r = certify(inst, text.str(), model);
  if (!r.proved) {
    // "line N: what" becomes FILE:N: (the message convention of every reader).
    long line = 0;
    size_t end = 0;
    if (r.reason.rfind("line ", 0) == 0 && (end = r.reason.find(": ")) != std::string::npos)
      line = std::stol(r.reason.substr(5, end - 5));
    throw UserError(
        Diagnostic{cert_path, line, "certificate rejected: " + (line ? r.reason.substr(end + 2) : r.reason)});
  }
  Answer ans("certify", vm.count("json") > 0);
  ans.comment("gridlock certify " + path + " " + cert_path + ": " + r.kind + ", " + model + " model");
  if (r.kind == "gaps")
    ans.comment(std::to_string(r.inequalities) + " gap inequalities derived, " + std::to_string(r.axioms) +
                " closure clauses, " + std::to_string(r.lemmas) + " lemmas checked");
  if (r.kind == "collide") {
    const std::string groups =
        r.one_axis ? "one axis, " + std::to_string(r.axioms) + " pairs in row groups (a first collision is in one), "
        : r.kept_axis == 3 ? "one coupling, groups over time slabs each keeping an order, " + std::to_string(r.axioms) +
                                 " pairs of their sweeps (if none overlaps, nothing does), "
        : r.kept_axis == 2 ? "one coupling, separated groups each keeping an order, " + std::to_string(r.axioms) +
                                 " pairs of their sweeps (if none overlaps, nothing does), "
        : r.kept_axis >= 0
            ? std::string("one coupling, the ") + (r.kept_axis == 0 ? "x" : "y") + " order kept, " +
                  std::to_string(r.axioms) + " pairs of the sweep along it (if none overlaps, nothing does), "
            : "";
    ans.comment("no schedule collides (gridlock collide's NO, in both models): " + groups +
                std::to_string(r.inequalities) + " pairs of regions kept apart by their multipliers, " +
                std::to_string(r.lemmas) + " by one form");
  }
  if (r.kind == "bounds")
    ans.comment(std::to_string(r.inequalities) + " clauses checked against the instance, " + std::to_string(r.axioms) +
                " selector definitions, " + std::to_string(r.lemmas) + " lemmas checked");
  ans.comment("certificate checked");
  ans.data()["kind"] = r.kind;
  ans.data()["model"] = model;
  ans.data()["lemmas"] = r.lemmas;
  if (r.one_axis) ans.data()["row_group_pairs"] = r.axioms;
  if (r.kept_axis >= 0)
    ans.data()["kept_order_pairs"] = r.axioms, ans.data()["kept_axis"] = r.kept_axis == 0   ? "x"
                                                                         : r.kept_axis == 1 ? "y"
                                                                         : r.kept_axis == 2 ? "separated"
                                                                                            : "slabs";
  return ans.finish(Verdict::No);
}

Command reg{"certify", "check a NO certificate independently of the solvers", run_certify};

}  // namespace
}  // namespace gridlock
