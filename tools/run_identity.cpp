#include "tools/run_identity.hpp"

#include <openssl/evp.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "tools/user_error.hpp"

namespace gridlock::cli {

std::string sha256_hex(std::string_view data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  if (EVP_Digest(data.data(), data.size(), digest, &len, EVP_sha256(), nullptr) != 1)
    throw UserError("internal: SHA-256 failed");
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < len; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 15];
  }
  return out;
}

nlohmann::json input_list(const std::vector<std::string>& paths, const std::string& stdin_text) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : paths) {
    std::string text = stdin_text;
    if (p != "-") {
      std::ifstream in(p, std::ios::binary);
      if (!in) throw UserError(p + ": cannot read file");
      std::ostringstream ss;
      ss << in.rdbuf();
      text = ss.str();
    }
    list.push_back({{"file", p}, {"sha256", sha256_hex(text)}});
  }
  return list;
}

nlohmann::json run_json(const std::string& command, const nlohmann::json& options, const nlohmann::json& inputs) {
  return {{"command", command}, {"options", options}, {"inputs", inputs}};
}

std::string run_id(const nlohmann::json& run) { return sha256_hex(run.dump()).substr(0, 16); }

void refuse_name_clashes(const std::vector<std::string>& paths, const std::string& what) {
  std::map<std::string, std::string> seen;
  for (const auto& p : paths) {
    const std::string stem = p == "-" ? "stdin" : std::filesystem::path(p).stem().string();
    auto [it, fresh] = seen.emplace(stem, p);
    if (fresh) continue;
    std::string msg = p;
    msg.append(": two inputs named '").append(stem).append("' (").append(it->second).append(" and ").append(p);
    msg.append(") would share ").append(what).append(": rename one");
    throw UserError(msg);
  }
}

}  // namespace gridlock::cli
