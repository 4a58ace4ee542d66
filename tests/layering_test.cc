// The layers of the source tree: each folder includes only the folders below
// it (README, "Architecture"), so the library never depends on the tool.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

// Folder -> the project folders its sources may include (itself aside).
const std::map<std::string, std::set<std::string>> kMayInclude = {
    {"model", {}},
    {"datasets", {"model"}},
    {"estimation", {"model", "datasets"}},
    {"report", {"model", "datasets", "estimation"}},
    {"validation", {"model", "datasets", "estimation", "report"}},
    {"apps", {"model", "datasets", "estimation", "report", "validation"}},
    // validation/: the speed cases shared with `ringid bench --suite=speed`.
    {"benchmarks", {"model", "datasets", "estimation", "report", "validation"}},
    {"examples", {"model", "datasets", "estimation", "report"}},
};

TEST(LayeringTest, EachFolderIncludesOnlyTheFoldersBelowIt) {
  const std::regex include(R"re(^\s*#\s*include\s+[<"](?:ringid/)?([a-z_]+)/)re");
  int checked = 0;
  for (const auto& [folder, allowed] : kMayInclude) {
    const fs::path dir = fs::path(RINGID_SOURCE_DIR) / folder;
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".h" && ext != ".cc") continue;
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        std::smatch m;
        if (!std::regex_search(line, m, include)) continue;
        const std::string target = m[1];
        if (target == folder) continue;
        if (target == "tests") ADD_FAILURE() << entry.path().string() << ":" << n << " includes tests/";
        if (!kMayInclude.count(target)) continue;  // a library
        ++checked;
        EXPECT_TRUE(allowed.count(target))
            << entry.path().string() << ":" << n << " includes " << target << "/";
      }
    }
  }
  EXPECT_GT(checked, 50);  // the scan found the includes it is about
}

}  // namespace
