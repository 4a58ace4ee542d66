// The layers of the source tree: each folder includes only the folders below
// it (README, "Architecture"), so the library never depends on the tool.
#include <filesystem>
#include <functional>
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
    {"operations", {"model", "datasets", "estimation", "report"}},
    {"validation", {"model", "datasets", "estimation", "report"}},
    {"apps", {"model", "datasets", "estimation", "report", "operations", "validation"}},
    // validation/: the speed cases shared with `ringid bench --suite=speed`.
    {"benchmarks", {"model", "datasets", "estimation", "report", "validation"}},
    {"examples", {"model", "datasets", "estimation", "report", "operations"}},
    // The Python module: the library's operations, in-process; only its
    // public headers (PythonUsesOnlyThePublicLibrary).
    {"python", {"model", "datasets", "estimation", "report", "operations"}},
};

// The project headers listed in cmake/public_headers.txt.
std::set<std::string> PublicHeaders() {
  std::ifstream list(fs::path(RINGID_SOURCE_DIR) / "cmake/public_headers.txt");
  std::set<std::string> is_public;
  for (std::string line; std::getline(list, line);) {
    if (!line.empty() && line[0] != '#') is_public.insert(line);
  }
  return is_public;
}

// Calls line(path, number, text) for every line of the sources below
// `folder` whose extension is one of `extensions`; the number of files read.
int ForEachLine(const std::string& folder, const std::set<std::string>& extensions,
                const std::function<void(const fs::path&, int, const std::string&)>& line) {
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(RINGID_SOURCE_DIR) / folder)) {
    if (!extensions.count(entry.path().extension().string())) continue;
    ++files;
    std::ifstream in(entry.path());
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) line(entry.path(), n, text);
  }
  return files;
}

TEST(LayeringTest, EachFolderIncludesOnlyTheFoldersBelowIt) {
  const std::regex include(R"re(^\s*#\s*include\s+[<"](?:ringid/)?([a-z_]+)/)re");
  int checked = 0;
  for (const auto& [folder, allowed] : kMayInclude) {
    const fs::path dir = fs::path(RINGID_SOURCE_DIR) / folder;
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    ForEachLine(folder, {".h", ".cc"}, [&, &folder = folder, &allowed = allowed](
                                           const fs::path& path, int n, const std::string& line) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) return;
      const std::string target = m[1];
      if (target == folder) return;
      if (target == "tests") ADD_FAILURE() << path.string() << ":" << n << " includes tests/";
      if (!kMayInclude.count(target)) return;  // a library
      ++checked;
      EXPECT_TRUE(allowed.count(target)) << path.string() << ":" << n << " includes " << target << "/";
    });
  }
  EXPECT_GT(checked, 50);  // the scan found the includes it is about
}

// The installed headers (cmake/public_headers.txt) include only each other:
// the install tree compiles, and no internal unit leaks into the API.
TEST(LayeringTest, PublicHeadersIncludeOnlyPublicHeaders) {
  const std::set<std::string> is_public = PublicHeaders();
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

// The Python module is written against the installed library (issue 34): it
// includes only public headers, so it builds against an install, and never
// the command line's flags (gflags), which are process-wide.
TEST(LayeringTest, PythonUsesOnlyThePublicLibrary) {
  const std::set<std::string> is_public = PublicHeaders();
  const std::regex project(R"re(^\s*#\s*include\s+[<"](?:ringid/)?([a-z_]+/[a-z_]+\.h)[>"])re");
  const std::regex gflags(R"re(gflags|GFLAGS|DEFINE_[a-z]|DECLARE_[a-z])re");
  int checked = 0;
  ForEachLine("python", {".h", ".cc"}, [&](const fs::path& path, int n, const std::string& line) {
    std::smatch m;
    EXPECT_FALSE(std::regex_search(line, gflags)) << path.string() << ":" << n << ": " << line;
    if (!std::regex_search(line, m, project)) return;
    const std::string folder = m[1].str().substr(0, m[1].str().find('/'));
    if (folder == "python" || !kMayInclude.count(folder)) return;  // itself, or a library
    ++checked;
    EXPECT_TRUE(is_public.count(m[1])) << path.string() << ":" << n << " includes " << m[1]
                                       << ", which is not installed";
  });
  EXPECT_GT(checked, 10);
}

// A user's clone has no shared folder beside it: only the corpus accessor of
// tests/test_support.cc names it; every other test reads tests/data or skips
// through testing::CorpusTest.
TEST(LayeringTest, NoTestReadsTheSharedFolderButThroughTheCorpusAccessor) {
  const std::string needle = std::string("..") + "/shared";  // not this line itself
  int scanned = 0;
  for (const char* folder : {"tests", "python", "benchmarks", "validation"}) {
    scanned += ForEachLine(folder, {".h", ".cc", ".py", ".sh", ".txt"},
                           [&](const fs::path& path, int n, const std::string& line) {
                             if (path.stem() == "test_support") return;
                             EXPECT_EQ(line.find(needle), std::string::npos)
                                 << path.string() << ":" << n << " reads the shared folder directly";
                           });
  }
  EXPECT_GT(scanned, 30);
}

}  // namespace
