#include "apps/command_line.h"

#include <algorithm>
#include <optional>

#include <gflags/gflags.h>

#include "model/spelling.h"

namespace ringid {
namespace {

bool Takes(const Command& c, const std::string& flag) {
  return std::find(c.flags.begin(), c.flags.end(), flag) != c.flags.end();
}

bool IsBool(const std::string& flag) {
  gflags::CommandLineFlagInfo info;
  return gflags::GetCommandLineFlagInfo(flag.c_str(), &info) && info.type == "bool";
}

// Why `flag` is not one of `command`'s, and what the user may have meant.
std::string NotAFlagOf(const std::string& flag, const Command& command,
                       const std::vector<Command>& all) {
  std::string takers;
  for (const Command& c : all) {
    if (Takes(c, flag)) takers += (takers.empty() ? "" : ", ") + c.name;
  }
  const std::string see = "see 'ringid " + command.name + " --help'";
  if (!takers.empty()) {
    return "--" + flag + ": not a flag of '" + command.name + "' (it is one of " + takers +
           "); " + see;
  }
  std::vector<std::string> names = command.flags;
  for (const std::string& f : command.flags) {
    if (IsBool(f)) names.push_back("no" + f);
  }
  const auto nearest = NearestName(flag, names);
  return "--" + flag + ": unknown flag for '" + command.name + "'" +
         (nearest ? " (did you mean --" + *nearest + "?)" : "") + "; " + see;
}

// What a value of gflags' `type` looks like, for a message.
std::string Expected(const std::string& type) {
  if (type == "bool") return "true or false";
  if (type == "double") return "a number";
  if (type == "string") return "text";
  return "an integer";
}

}  // namespace

bool WantsHelp(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") return true;
  }
  return false;
}

const Command* FindCommand(const std::vector<Command>& all, const std::string& name) {
  for (const Command& c : all) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

bool SetFlags(int argc, char** argv, const Command& command,
              const std::vector<Command>& all, std::string* error) {
  std::string bare_bool;  // the flag just before, if a boolean given alone
  for (int i = 2; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      *error = "unexpected argument '" + arg + "'";
      if (!bare_bool.empty()) {  // --shapes false
        *error += " (a boolean takes --" + bare_bool + "=" + arg + ", or --" + bare_bool +
                  " or --no" + bare_bool + " alone)";
      }
      return false;
    }
    bare_bool.clear();
    arg = arg.substr(2);
    const size_t eq = arg.find('=');
    std::string name = arg.substr(0, eq);
    std::optional<std::string> value;
    if (eq != std::string::npos) value = arg.substr(eq + 1);
    // --noNAME: a boolean turned off, as gflags spells it.
    if (!Takes(command, name) && name.rfind("no", 0) == 0 && Takes(command, name.substr(2)) &&
        IsBool(name.substr(2))) {
      if (value) {
        *error = "--" + name + ": takes no value (or write --" + name.substr(2) + "=false)";
        return false;
      }
      name = name.substr(2);
      value = "false";
    }
    gflags::CommandLineFlagInfo info;
    if (!Takes(command, name) || !gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
      *error = NotAFlagOf(name, command, all);
      return false;
    }
    if (!value && info.type == "bool") {
      value = "true";  // a boolean never takes the next argument (as in gflags)
      bare_bool = name;
    } else if (!value) {
      // --NAME VALUE; an argument that is itself a flag is not a value.
      if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0) {
        *error = "--" + name + ": needs a value (--" + name + "=VALUE or --" + name + " VALUE)";
        return false;
      }
      value = argv[++i];
    }
    if (!SetFlagValue(name, *value, error)) return false;
  }
  return true;
}

bool SetFlagValue(const std::string& name, const std::string& value, std::string* error) {
  if (!gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty()) return true;
  gflags::CommandLineFlagInfo info;
  gflags::GetCommandLineFlagInfo(name.c_str(), &info);
  *error = "--" + name + ": bad value '" + value + "' (" + Expected(info.type) + " expected)";
  return false;
}

}  // namespace ringid
