#include "apps/help.h"

#include <gflags/gflags.h>

#include "model/effects.h"
#include "model/spelling.h"
#include "operations/option_text.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// How a flag is given, shown after the commands.
const char kFlagSyntax[] =
    "Give a flag as --NAME=VALUE or --NAME VALUE; a boolean alone (--shapes) is\n"
    "true, and --noNAME (--noshapes) false.\n";

const char kExitStatus[] =
    "exit status:\n"
    "  0    success\n"
    "  1    the run finished but the analysis failed (the report says why)\n"
    "  2    bad input: unreadable or malformed file, unknown or bad flag,\n"
    "       unwritable output; one line on stderr, nothing written\n"
    "  130  interrupted (Ctrl-C; 143 for SIGTERM): one line on stderr says what\n"
    "       was kept (nothing, or a campaign's finished reports)\n";

// `text` with every line indented by `indent`.
std::string Indented(const std::string& text, const std::string& indent) {
  std::string out;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end == std::string::npos ? end : end - start);
    out += (line.empty() ? "" : indent) + line + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

// `text` broken into lines of at most `width` characters after `indent`.
std::string Wrapped(const std::string& text, const std::string& indent, size_t width = 78) {
  std::string out, line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && indent.size() + line.size() + 1 + word.size() > width) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + indent + line + "\n";
}

// "--NAME=N  (default 4)" and the like, from gflags' record of the flag; a
// flag that takes one of the library's names shows them: --method=lm|simplex.
std::string FlagLine(const gflags::CommandLineFlagInfo& info,
                     const std::vector<std::string>& values) {
  std::string line = "--" + info.name;
  std::string value = info.default_value;
  if (info.type == "bool") {
    line += "[=BOOL]";
    value += "; --no" + info.name + " for false";
  } else if (info.type == "string") {
    std::string names;
    for (const std::string& v : values) names += (names.empty() ? "" : "|") + v;
    line += "=" + (values.empty() ? "TEXT" : info.name == "effects" ? "LIST" : names);
    value = value.empty() ? "none" : "'" + value + "'";
  } else if (info.type == "double") {
    line += "=X";
  } else {
    line += "=N";
  }
  return line + "  (default " + value + ")";
}

std::string Usage(const Command& c) {
  std::string line = "ringid " + c.name;
  if (!c.usage.empty()) line += " " + c.usage;
  if (!c.flags.empty()) line += " [FLAG ...]";
  return line;
}

}  // namespace

std::vector<std::string> FlagValues(const std::string& flag) {
  if (const OptionInfo* o = FindOption(flag)) return o->choices;
  if (flag == "format") return {"tir", "json"};  // export's
  if (flag == "suite") {
    std::vector<std::string> names;
    for (const SuiteEntry& s : Suites()) names.push_back(s.name);
    return names;
  }
  return {};
}

std::string TirReaders(const std::vector<Command>& all) {
  std::vector<std::string> names;
  for (const Command& c : all) {
    if (c.reads_tir) names.push_back(c.name + (c.reads_tir->empty() ? "" : " --" + *c.reads_tir));
  }
  std::string list;
  for (size_t i = 0; i < names.size(); ++i) {
    list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  }
  return "--parameters of " + list + " also reads the rigid-ring part of an MF-Swift FILE.tir "
         "(docs/tir.md), what a .tir cannot hold given by --set";
}

std::string Help(const std::vector<Command>& commands) {
  std::string help =
      "ringid: identify rigid-ring (SWIFT) tire parameters from modal test data\n"
      "\n"
      "usage: ringid COMMAND [--flag=value ...]\n"
      "       ringid COMMAND --help    the command's flags, their defaults and meaning\n"
      "\n"
      "commands:\n";
  for (const Command& c : commands) {
    help += "  " + Usage(c) + "\n" + Indented(c.summary, "      ");
  }
  help += "\n" + std::string(kFlagSyntax) + "\n" +
          Wrapped("effects: " + OneOf(FlagValues("effects")), "") + "\n" +
          Wrapped("a .tir: " + TirReaders(commands) + ".", "") + "\n" + kExitStatus;
  return help;
}

std::string CommandHelp(const Command& c, const std::vector<Command>& all) {
  std::string help = "usage: " + Usage(c) + "\n\n" + c.summary + "\n";
  if (c.summary.empty() || c.summary.back() != '\n') help += "\n";
  if (c.flags.empty()) return help + "It takes no flags.\n";
  help += "flags:\n";
  for (const std::string& name : c.flags) {
    const gflags::CommandLineFlagInfo info = gflags::GetCommandLineFlagInfoOrDie(name.c_str());
    const std::vector<std::string> values = FlagValues(name);
    std::string meaning = info.description;
    if (name == "effects") meaning += "; LIST is any of " + OneOf(values);
    if (name == "parameters") meaning += "; " + TirReaders(all);
    help += "  " + FlagLine(info, values) + "\n" + Wrapped(meaning, "      ");
  }
  return help + "\n" + kFlagSyntax;
}

std::string CommandsMarkdown(const std::vector<Command>& all) {
  std::string md =
      "# Every command and its flags\n\n"
      "<!-- generated by `ringid commands > docs/commands.md`; a test keeps it equal -->\n"
      "What `ringid help` and `ringid COMMAND --help` print. How the commands fit together, by\n"
      "workflow: [the guides](guides/commands.md).\n\n"
      "```text\n" + Help(all) + "```\n";
  for (const Command& c : all) md += "\n## " + c.name + "\n\n```text\n" + CommandHelp(c, all) + "```\n";
  return md;
}

}  // namespace ringid
