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
    // The Python module: the command line's flags and commands, in-process.
    {"python", {"model", "datasets", "estimation", "report", "validation", "apps"}},
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

// The installed headers (cmake/public_headers.txt) include only each other:
// the install tree compiles, and no internal unit leaks into the API.
TEST(LayeringTest, PublicHeadersIncludeOnlyPublicHeaders) {
  std::ifstream list(fs::path(RINGID_SOURCE_DIR) / "cmake/public_headers.txt");
  ASSERT_TRUE(list.good());
  std::set<std::string> is_public;
  for (std::string line; std::getline(list, line);) {
    if (!line.empty() && line[0] != '#') is_public.insert(line);
  }
  ASSERT_GT(is_public.size(), 20u);
  const std::regex include(R"re(^\s*#\s*include\s+"([a-z_]+/[a-z_]+\.h)")re");
  int checked = 0;
  for (const std::string& header : is_public) {
    std::ifstream in(fs::path(RINGID_SOURCE_DIR) / header);
    ASSERT_TRUE(in.good()) << header << " is listed but missing";
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      ++checked;
      EXPECT_TRUE(is_public.count(m[1])) << header << ":" << n << " includes " << m[1]
                                          << ", which is not public";
    }
  }
  EXPECT_GT(checked, 30);
}

// A user's clone has no shared folder beside it: only the corpus accessor of
// tests/test_support.cc names it; every other test reads tests/data or skips
// through testing::CorpusTest.
TEST(LayeringTest, NoTestReadsTheSharedFolderButThroughTheCorpusAccessor) {
  const std::string needle = std::string("..") + "/shared";  // not this line itself
  int scanned = 0;
  for (const char* folder : {"tests", "python", "benchmarks", "validation"}) {
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(RINGID_SOURCE_DIR) / folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".h" && ext != ".cc" && ext != ".py" && ext != ".sh" && ext != ".txt") continue;
      if (entry.path().stem() == "test_support") continue;
      ++scanned;
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        EXPECT_EQ(line.find(needle), std::string::npos)
            << entry.path().string() << ":" << n << " reads the shared folder directly";
      }
    }
  }
  EXPECT_GT(scanned, 30);
}

}  // namespace
