// `ringid help` and `ringid COMMAND --help`: the commands, their flags, and
// the names the flags take, drawn from the table of commands
// (apps/command_line.h), the flags' definitions and the library's names.
#ifndef RINGID_APPS_HELP_H_
#define RINGID_APPS_HELP_H_

#include <string>
#include <vector>

#include "apps/command_line.h"

namespace ringid {

// Every command with what it needs and does.
std::string Help(const std::vector<Command>& commands);

// One command of `all`: its usage, what it does, and each of its flags with
// its type, default and meaning (the flag's DEFINE) and, where the library
// names them, the values it takes.
std::string CommandHelp(const Command& command, const std::vector<Command>& all);

// docs/commands.md: the overview of Help and each command's CommandHelp.
std::string CommandsMarkdown(const std::vector<Command>& all);

// The commands of `all` whose --parameters reads a .tir (Command::reads_tir),
// as a sentence.
std::string TirReaders(const std::vector<Command>& all);

// The values a flag takes where the library names them (--method: lm,
// simplex; --effects: the catalogue); empty for a free value.
std::vector<std::string> FlagValues(const std::string& flag);

}  // namespace ringid

#endif  // RINGID_APPS_HELP_H_
