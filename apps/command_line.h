// The command line of ringid: one table of commands, each with the flags it
// takes. SetFlags reads argv into gflags from that table, and each command's
// --help is drawn from it and the flags' own definitions (DEFINE_* in
// apps/flags.cc), so no second list of flags can drift from the first.
#ifndef RINGID_APPS_COMMAND_LINE_H_
#define RINGID_APPS_COMMAND_LINE_H_

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ringid {

// The exit status of every command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the analysis ran but failed numerically
inline constexpr int kExitUsage = 2;    // bad input: file, field or flag

struct Command {
  std::string name;
  std::string usage;    // the flags it cannot run without, e.g. "--dataset=FILE"
  std::string summary;  // what it does, in lines of at most 72 characters
  std::vector<std::string> flags;  // every flag it takes, in help order
  std::function<int(int argc, char** argv)> run;
  // Whether its --parameters reads an MF-Swift .tir (docs/tir.md): always
  // (""), only with the flag named, or not (nullopt). The help lists these.
  std::optional<std::string> reads_tir = std::nullopt;
};

// Sets the flags of argv[2..] through gflags, each as --NAME=VALUE or
// --NAME VALUE; a boolean alone is true and --noNAME false. False with one
// line naming the flag on anything else: a flag `command` does not take (with
// the nearest one it takes, or the commands that take it), a missing or bad
// value, a stray argument.
bool SetFlags(int argc, char** argv, const Command& command,
              const std::vector<Command>& all, std::string* error);
// --NAME=VALUE of a flag gflags knows; false with the line naming it.
bool SetFlagValue(const std::string& name, const std::string& value, std::string* error);

// Whether argv[2..] asks for help: --help or -h.
bool WantsHelp(int argc, char** argv);

// Two lists of flags, one after the other.
inline std::vector<std::string> Joined(std::vector<std::string> a,
                                       const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The command called `name`, or null.
const Command* FindCommand(const std::vector<Command>& all, const std::string& name);

}  // namespace ringid

#endif  // RINGID_APPS_COMMAND_LINE_H_
