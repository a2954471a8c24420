#include "tools/set_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/internal/atomic_file.hpp"
#include "tools/cli_common.hpp"
#include "tools/run_identity.hpp"
#include "tools/user_error.hpp"

namespace gridlock::cli {

namespace fs = std::filesystem;

namespace {

const char* const kLedger = ".gridlock-files";
const char* const kRunFile = "run.json";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Is name a plain file name (no folder part)? Ledger and manifest entries
// that are not are ignored: --force never reaches outside the folder.
bool plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

// "manifest.json" or "manifest-shard-K-of-N.json": the shard K it belongs to
// (0 for manifest.json), or -1 for another name.
int64_t manifest_shard(const std::string& name) {
  if (name == "manifest.json") return 0;
  unsigned long long k = 0, n = 0;
  char tail[8] = {};
  if (std::sscanf(name.c_str(), "manifest-shard-%llu-of-%llu%7s", &k, &n, tail) == 3 && std::string(tail) == ".json")
    return static_cast<int64_t>(k);
  return -1;
}

// The files gridlock wrote in dir (only shard k's if k >= 0): the ledger's,
// the manifests' entries and the manifests, and our temporary files.
std::set<std::string> own_files(const fs::path& dir, int64_t k) {
  std::set<std::string> own;
  std::istringstream ledger(slurp(dir / kLedger));
  for (std::string line; std::getline(ledger, line);) {
    std::istringstream ls(line);
    int64_t shard = -1;
    std::string name;
    if (ls >> shard >> name && plain_name(name) && (k < 0 || shard == k)) own.insert(name);
  }
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const int64_t mk = manifest_shard(name);
    if (name.find(".tmp.") != std::string::npos && k < 0) own.insert(name);
    if (mk < 0 || (k >= 0 && mk != k)) continue;
    auto m = nlohmann::json::parse(slurp(e.path()), nullptr, false);
    if (m.is_discarded() || !m.is_object() || m.value("generator", "") != "gridlock gen-instances") continue;
    own.insert(name);
    if (!m.contains("instances") || !m["instances"].is_array()) continue;
    for (const auto& x : m["instances"]) {
      if (!x.is_object()) continue;
      for (const char* key : {"instance", "formula"})
        if (x.contains(key) && x[key].is_string()) own.insert(x[key].get<std::string>());
      if (x.contains("certificate") && x["certificate"].is_object() && x["certificate"].contains("file") &&
          x["certificate"]["file"].is_string())
        own.insert(x["certificate"]["file"].get<std::string>());
    }
  }
  std::erase_if(own, [](const std::string& n) { return !plain_name(n); });
  return own;
}

// Removes names from dir: manifests first (a folder is never described by a
// stale manifest), after checking that none is an input.
void remove_own(const fs::path& dir, const std::set<std::string>& names) {
  std::vector<std::string> order(names.begin(), names.end());
  std::stable_partition(order.begin(), order.end(), [](const std::string& n) { return manifest_shard(n) >= 0; });
  for (const auto& n : order)
    if (std::string in = protected_input_at((dir / n).string()); !in.empty())
      throw UserError(Diagnostic{(dir / n).string(), 0, "will not remove the input " + in + " (--force)"});
  for (const auto& n : order)
    if (auto err = remove_own_file((dir / n).string())) throw UserError(*err);
}

// The run id in dir/run.json, "" if there is none, "?" if it is unreadable.
std::string folder_run_id(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / kRunFile, ec)) return "";
  auto j = nlohmann::json::parse(slurp(dir / kRunFile), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("run_id") || !j["run_id"].is_string()) return "?";
  return j["run_id"].get<std::string>();
}

// Creates dir/run.json with this run unless it exists (link(): exclusive, so
// two shards starting together agree on one); then it must be this run's.
void claim_folder(const SetFolder& f) {
  const fs::path dir(f.dir);
  nlohmann::json j = f.run;
  j["run_id"] = run_id(f.run);
  StagedFile staged;
  const std::string target = (dir / kRunFile).string();
  std::string tmp = target + ".tmp.XXXXXX";
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) throw UserError(Diagnostic{f.dir, 0, std::string("cannot write in folder: ") + std::strerror(errno)});
  const std::string text = j.dump(2) + "\n";
  int err = 0;
  bool ok = detail::write_all(fd, text, err);
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  const bool linked = ok && ::link(tmp.c_str(), target.c_str()) == 0;
  if (ok && !linked && errno != EEXIST) ok = false, err = errno;
  ::unlink(tmp.c_str());
  if (!ok) throw UserError(Diagnostic{target, 0, std::string("write failed: ") + std::strerror(err)});
  const std::string id = folder_run_id(dir);
  if (id != j["run_id"].get<std::string>())
    throw UserError(Diagnostic{f.dir, 0,
                               "holds a set of another run (run.json: run_id " + id +
                                   ", this run: " + j["run_id"].get<std::string>() +
                                   "; options, seed or inputs differ): give another folder"});
}

}  // namespace

bool folder_empty(const std::string& dir) {
  std::error_code ec;
  return fs::directory_iterator(dir, ec) == fs::directory_iterator();
}

void check_writable_folder(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UserError(Diagnostic{dir, 0, "exists and is not a folder"});
  fs::create_directories(dir, ec);
  if (ec) throw UserError(Diagnostic{dir, 0, "cannot create folder: " + ec.message()});
  std::string probe = (fs::path(dir) / ".gridlock-probe.tmp.XXXXXX").string();
  int fd = ::mkstemp(probe.data());
  if (fd < 0) throw UserError(Diagnostic{dir, 0, std::string("cannot write in folder: ") + std::strerror(errno)});
  ::close(fd);
  ::unlink(probe.c_str());
}

void check_folder_can_be_made(const std::string& dir) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (ec) throw UserError(Diagnostic{dir, 0, "cannot use folder: " + ec.message()});
  while (!p.empty() && !fs::exists(p, ec)) {
    if (p == p.parent_path()) break;
    p = p.parent_path();
  }
  if (!fs::is_directory(p, ec))
    throw UserError(Diagnostic{dir, 0,
                               p.string() == fs::absolute(dir, ec).lexically_normal().string()
                                   ? "exists and is not a folder"
                                   : "cannot create folder: " + p.string() + " is not a folder"});
  if (::access(p.c_str(), W_OK | X_OK) != 0)
    throw UserError(Diagnostic{dir, 0, "cannot write in folder " + p.string() + ": " + std::strerror(errno)});
}

void prepare_set_folder(const SetFolder& f, const std::string& manifest_name, bool force) {
  check_writable_folder(f.dir);
  const fs::path dir(f.dir);
  const std::string id = folder_run_id(dir);
  if (f.shard_n == 1) {
    if (!folder_empty(dir)) {
      if (!force) throw UserError(Diagnostic{f.dir, 0, "folder is not empty (give --force to replace the set in it)"});
      std::set<std::string> own = own_files(dir, -1);
      own.insert(kRunFile);
      own.insert(kLedger);
      remove_own(dir, own);
    }
  } else {
    if (id.empty() && !folder_empty(dir))
      throw UserError(Diagnostic{f.dir, 0,
                                 "folder is not empty and holds no run.json: shards share only a folder of their "
                                 "own run (give an empty folder)"});
    const std::set<std::string> own = id == run_id(f.run) ? own_files(dir, static_cast<int64_t>(f.shard_k))
                                                          : std::set<std::string>{};
    if (!own.empty()) {
      if (!force)
        throw UserError(Diagnostic{(dir / manifest_name).string(), 0,
                                   "this shard was already written here (give --force to write it again)"});
      remove_own(dir, own);
    }
  }
  claim_folder(f);
}

void write_set_file(const SetFolder& f, const std::string& name, const std::string& text) {
  const std::string path = (fs::path(f.dir) / name).string();
  std::error_code ec;
  if (fs::exists(path, ec))
    throw UserError(Diagnostic{path, 0, "exists and was not written by this run: remove it or give another folder"});
  const std::string line = std::to_string(f.shard_k) + " " + name + "\n";
  const std::string ledger = (fs::path(f.dir) / kLedger).string();
  int fd = ::open(ledger.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  int err = 0;
  bool ok = fd >= 0 && detail::write_all(fd, line, err);
  if (fd < 0) err = errno;
  if (fd >= 0 && ::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) throw UserError(Diagnostic{ledger, 0, std::string("write failed: ") + std::strerror(err)});
  write_text_file(path, text);
}

}  // namespace gridlock::cli
