// What makes the results of one run one set (docs/errors.md, "Sets carry
// their identity"): the command, the options that change results, the seed,
// and every input with the SHA-256 of its content. Shards of a run and the
// files of a gen-instances folder carry it ("run" and "run_id"), and
// 'gridlock merge' and a shared gen-instances folder refuse what differs.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridlock::cli {

// SHA-256 of data, 64 lower-case hex digits (OpenSSL).
std::string sha256_hex(std::string_view data);

// [{"file": PATH, "sha256": HEX}, ...] for the files a run reads, hashing
// what is in them now ("-": hashes stdin_text, the input as read).
nlohmann::json input_list(const std::vector<std::string>& paths, const std::string& stdin_text = "");

// {"command", "options", "inputs"} and its id: the first 16 hex digits of
// the SHA-256 of the object's compact dump (keys sorted by nlohmann::json).
nlohmann::json run_json(const std::string& command, const nlohmann::json& options, const nlohmann::json& inputs);
std::string run_id(const nlohmann::json& run);

// Throws UserError("NAME: two inputs named NAME: A and B ...") when two
// paths give the same output name (their file stem).
void refuse_name_clashes(const std::vector<std::string>& paths, const std::string& what);

}  // namespace gridlock::cli
