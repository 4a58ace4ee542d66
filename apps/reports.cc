#include "apps/reports.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include "apps/interrupt.h"

namespace ringid {

using nlohmann::json;

bool CanWrite(const std::string& path, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    *error = path + ": is a directory, not a file";
    return false;
  }
  const auto hold = HoldInterruption();  // an interruption leaves no probe behind
  const std::string probe = path + ".ringid-probe";
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) {
    *error = path + ": cannot write: " + std::strerror(errno);
    return false;
  }
  std::fclose(f);
  std::remove(probe.c_str());
  return true;
}

namespace {

namespace fs = std::filesystem;

// `path` with its directories resolved where they exist (".", "..", symbolic
// links), so that two spellings of one file compare equal.
fs::path Resolved(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : p;
}

}  // namespace

bool SameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  return Resolved(a) == Resolved(b) || fs::equivalent(a, b, ec);
}

bool CheckOutputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                  const std::vector<std::pair<std::string, std::string>>& inputs,
                  std::string* error) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const auto& [flag, path] = outputs[i];
    if (path.empty()) continue;
    for (size_t j = 0; j < i; ++j) {
      if (!outputs[j].second.empty() && SameFile(path, outputs[j].second)) {
        *error = "--" + flag + ": " + path + " is also --" + outputs[j].first +
                 "; give each output its own file";
        return false;
      }
    }
    for (const auto& [input_flag, input] : inputs) {
      if (!input.empty() && SameFile(path, input)) {
        *error = "--" + flag + ": " + path + " is the --" + input_flag +
                 " input, which it would overwrite";
        return false;
      }
    }
    if (!CanWrite(path, error)) {
      *error = "--" + flag + ": " + *error;
      return false;
    }
  }
  return true;
}

bool CanMakeDirectory(const std::string& dir, std::string* error) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // "figures/"
  fs::path existing = p;
  while (!fs::exists(existing, ec) && existing.has_relative_path()) {
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, ec)) {
    *error = dir + ": " + (existing == p ? std::string("not a directory")
                                         : existing.string() + " is not a directory");
    return false;
  }
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    *error = dir + ": cannot " + (existing == p ? "write in it" : "make it") + ": " +
             std::strerror(errno);
    return false;
  }
  return true;
}

bool MakeDirectory(const std::string& dir, std::vector<std::string>* made, std::string* error) {
  std::error_code ec;
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !fs::exists(p, ec);
       p = p.parent_path()) {
    if (p.has_filename()) missing.push_back(p);
    if (!p.has_relative_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      *error = dir + ": cannot make it: " + ec.message();
      RemoveMade(*made);
      return false;
    }
    made->push_back(it->string());
  }
  return true;
}

void RemoveMade(const std::vector<std::string>& made) {
  std::error_code ec;
  for (auto it = made.rbegin(); it != made.rend(); ++it) fs::remove(*it, ec);  // if empty
}

std::string JsonText(const nlohmann::json& report) {
  return report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace ringid
