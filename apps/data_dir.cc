#include "apps/data_dir.h"

#include <filesystem>
#include <system_error>

namespace ringid {
namespace {

namespace fs = std::filesystem;

// A directory with the shipped data in it.
bool HoldsData(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "datasets" / "paper" / "table1.json", ec);
}

}  // namespace

std::string DataDir() {
  std::error_code ec;
  // RINGID_DATA_FROM_BIN: the install's data directory relative to its
  // binary directory, set by CMakeLists.txt (e.g. "../share/ringid").
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = (exe.parent_path() / RINGID_DATA_FROM_BIN).lexically_normal();
    if (HoldsData(installed)) return installed.string();
  }
  if (HoldsData(RINGID_BUILT_FROM)) return RINGID_BUILT_FROM;
  return ".";
}

}  // namespace ringid
