// The folder of a gen-instances set: what gridlock wrote there, and whose
// run it belongs to (docs/errors.md, "Inputs are sacred" and "Sets carry
// their identity").
//
//   run.json         the run's identity (tools/run_identity.hpp), created
//                    once, atomically (link), by the first shard; every
//                    later shard must carry the same run_id
//   .gridlock-files  the ledger: one line "K NAME" per file shard K writes,
//                    appended before the file is written, so that even a
//                    killed run's files are known
//
// --force removes only what the ledger and the manifests list (and
// temporary *.tmp.* files of ours), never an input, never anything else.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace gridlock::cli {

struct SetFolder {
  std::string dir;
  uint64_t shard_k = 0, shard_n = 1;
  nlohmann::json run;  // run_json(...) of this run; run.json holds it with "run_id"
};

// Creates the folder (or checks it), checks that it is writable, and makes
// it this run's: unsharded, an empty folder, or with force one whose
// gridlock files are removed first; sharded, an empty folder or one whose
// run.json has this run's id (force: this shard's files are removed first).
// Throws UserError naming the folder or file otherwise. Nothing is removed
// unless every removal is allowed (no input among them).
void prepare_set_folder(const SetFolder& f, const std::string& manifest_name, bool force);

// Writes NAME in the folder: recorded in the ledger first; a file already
// there (not written by this run) is refused, never overwritten.
void write_set_file(const SetFolder& f, const std::string& name, const std::string& text);

// True iff dir holds nothing (or cannot be listed, e.g. it does not exist).
bool folder_empty(const std::string& dir);

// Throws UserError("DIR: cannot write in folder: REASON") unless a file can
// be created in dir (created first, with its parents).
void check_writable_folder(const std::string& dir);

// For a folder written only if something is found (reproducers): throws
// UserError("DIR: ...") unless dir is a writable folder, or could be created
// (its nearest existing ancestor is a writable folder). Creates nothing.
void check_folder_can_be_made(const std::string& dir);

}  // namespace gridlock::cli
