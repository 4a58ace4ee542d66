#include "operations/files.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace ringid {
namespace {

// Never destroyed: a signal's watcher thread may take it while static
// objects are torn down.
struct Written {
  std::recursive_mutex mutex;
  std::vector<std::string> files;
};
Written& Shared() {
  static Written* written = new Written;
  return *written;
}

}  // namespace

std::unique_lock<std::recursive_mutex> HoldFileWrites() {
  return std::unique_lock<std::recursive_mutex>(Shared().mutex);
}

const std::vector<std::string>& FilesWritten() { return Shared().files; }

bool WriteFileAtomically(const std::string& path, const std::string& text,
                         std::string* error) {
  return WriteFilesAtomically({{path, text}}, error);
}

bool WriteFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* error) {
  for (size_t i = 0; i < files.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (std::filesystem::path(files[i].first).lexically_normal() ==
          std::filesystem::path(files[j].first).lexically_normal()) {
        *error = files[i].first + ": named for two outputs";
        return false;
      }
    }
  }
  const auto hold = HoldFileWrites();  // an interruption waits for the whole group
  // Each file goes to a temporary beside it; an existing file is kept as a
  // hard link beside it until every rename has succeeded, so that a failed
  // rename puts back what was there (or removes what was not).
  const std::string suffix = "." + std::to_string(::getpid());
  std::vector<std::string> tmps, backups;
  auto fail = [&](const std::string& path) {
    *error = path + ": cannot write: " + std::strerror(errno);
    for (const std::string& t : tmps) std::remove(t.c_str());
    for (const std::string& b : backups) {
      if (!b.empty()) std::remove(b.c_str());
    }
    return false;
  };
  for (const auto& [path, text] : files) {
    tmps.push_back(path + ".tmp" + suffix);
    std::FILE* f = std::fopen(tmps.back().c_str(), "wb");
    if (!f) {
      tmps.pop_back();
      return fail(path);
    }
    const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !wrote) return fail(path);
    backups.emplace_back();
    if (files.size() > 1 && ::access(path.c_str(), F_OK) == 0) {
      backups.back() = path + ".old" + suffix;
      if (::link(path.c_str(), backups.back().c_str()) != 0) {
        backups.back().clear();
        return fail(path);
      }
    }
  }
  // Every file is complete before the first rename.
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(tmps[i].c_str(), files[i].first.c_str()) == 0) continue;
    const int rename_errno = errno;
    for (size_t j = 0; j < i; ++j) {  // put back the files renamed already
      if (backups[j].empty()) {
        std::remove(files[j].first.c_str());
      } else if (std::rename(backups[j].c_str(), files[j].first.c_str()) == 0) {
        backups[j].clear();
      }
    }
    tmps.erase(tmps.begin(), tmps.begin() + i);
    errno = rename_errno;
    return fail(files[i].first);
  }
  for (const std::string& b : backups) {
    if (!b.empty()) std::remove(b.c_str());
  }
  for (const auto& file : files) Shared().files.push_back(file.first);
  return true;
}

}  // namespace ringid
