#include "support/cnf_testing.hpp"

#include <algorithm>
#include <filesystem>

namespace gridlock::test {

Formula make_formula(int n, std::vector<std::vector<int>> clauses) {
  Formula f;
  f.num_vars = n;
  f.clauses = std::move(clauses);
  return f;
}

std::vector<SatlibFile> satlib_files() {
  std::vector<SatlibFile> files;
  const std::string root = GRIDLOCK_DATA_DIR "/satlib";
  for (const char* dir : {"uf20-91", "uf50-218", "uuf50-218"}) {
    const bool sat = dir[0] == 'u' && dir[1] == 'f';
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(root + "/" + dir, ec))
      if (e.path().extension() == ".cnf") files.push_back({e.path().string(), sat});
  }
  std::sort(files.begin(), files.end(), [](const SatlibFile& a, const SatlibFile& b) { return a.path < b.path; });
  return files;
}

Formula random_cnf(Rng& rng, int n, int m, int min_len, int max_len, bool messy) {
  Formula f;
  f.num_vars = n;
  for (int i = 0; i < m; ++i) {
    int len = static_cast<int>(rng.between(min_len, max_len));
    if (!messy) len = std::min(len, n);
    std::vector<int> c;
    while (static_cast<int>(c.size()) < len) {
      int v = static_cast<int>(rng.between(1, n));
      if (!messy && std::any_of(c.begin(), c.end(), [&](int x) { return var_of(x) == v; })) continue;
      c.push_back(rng.coin() ? v : -v);
    }
    f.clauses.push_back(std::move(c));
  }
  return f;
}

}  // namespace gridlock::test
