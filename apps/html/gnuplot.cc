#include "apps/html/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "apps/html/page.h"
#include "apps/html/text.h"

extern char** environ;

namespace ringid::html {
namespace {

bool WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  return static_cast<bool>(out);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Starts `program -d script` with stdin from /dev/null and output to `log`.
bool Spawn(const GnuplotRun& run, pid_t* pid, std::string* error) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<std::string> args = {run.program, "-d", run.script};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const int rc = posix_spawn(pid, run.program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc == 0) return true;
  *error = "cannot run " + run.program + ": " + std::strerror(rc);
  return false;
}

// Waits for `pid`, killing it after the timeout.
bool Wait(const GnuplotRun& run, pid_t pid, int* status, std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const pid_t done = ::waitpid(pid, status, WNOHANG);
    if (done == pid) return true;
    if (done < 0 && errno != EINTR) {
      *error = "lost the gnuplot process";
      return false;
    }
    if (std::chrono::steady_clock::now() - start >
        std::chrono::duration<double>(run.timeout_seconds)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, status, 0);
      *error = "gnuplot took longer than " + Format(run.timeout_seconds, "%.0f") + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// Whether `line` has gnuplot's "line N:", where it places its messages.
bool NamesAScriptLine(const std::string& line) {
  for (size_t i = line.find("line "); i != std::string::npos; i = line.find("line ", i + 1)) {
    size_t end = i + 5;
    while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) ++end;
    if (end > i + 5 && end < line.size() && line[end] == ':') return true;
  }
  return false;
}

// The line of gnuplot's log that says what went wrong: the first one that
// names an error or a script line, else the first one with text.
std::string ErrorLine(const std::string& log) {
  std::stringstream lines(log);
  std::string line, first;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.find("rror") != std::string::npos || NamesAScriptLine(line)) return line;
  }
  return first;
}

// The terminal, the data files' format and the house style.
std::string Preamble(const Figure& figure, const std::string& base) {
  std::ostringstream script;
  script << "set terminal svg size " << figure.width << "," << figure.height
         << " dynamic enhanced font 'sans,10'\n"
         << "set output " << GnuplotString(base + ".svg") << "\n"
         << "set encoding utf8\nset datafile separator \"\\t\"\nset datafile missing '?'\n"
         << "set key noenhanced\nset border lc rgb '#444444'\nset grid lc rgb '#e3e3e3' lt 1\n"
         << "set clip two\n";
  return script.str();
}

}  // namespace

TempDir::TempDir() {
  std::error_code ec;
  std::string base = std::filesystem::temp_directory_path(ec).string();
  if (ec || base.empty()) base = "/tmp";
  std::string pattern = base + "/ringid-report-XXXXXX";
  if (::mkdtemp(pattern.data())) path_ = pattern;
}

TempDir::~TempDir() {
  if (path_.empty()) return;
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

bool FindGnuplot(std::string* path) {
  const char* env = std::getenv("PATH");
  std::stringstream dirs(env ? env : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/gnuplot";
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      *path = candidate;
      return true;
    }
  }
  return false;
}

bool RunGnuplot(const GnuplotRun& run, std::string* error) {
  pid_t pid = 0;
  int status = 0;
  if (!Spawn(run, &pid, error) || !Wait(run, pid, &status, error)) return false;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  const std::string line = ErrorLine(ReadText(run.log));
  *error = "gnuplot failed" + (line.empty() ? std::string() : ": " + line);
  return false;
}

bool DrawSvg(const std::string& program, const Figure& figure, const std::string& dir,
             std::string* svg, std::string* error) {
  const std::string base = dir + "/" + figure.name;
  std::string script = Preamble(figure, base);
  for (size_t k = 0; k < figure.data.size(); ++k) {
    const std::string file = base + "." + std::to_string(k) + ".dat";
    if (!WriteText(file, figure.data[k])) {
      *error = "cannot write " + file;
      return false;
    }
    script += "d" + std::to_string(k) + " = " + GnuplotString(file) + "\n";
  }
  script += figure.script;
  if (!WriteText(base + ".gp", script)) {
    *error = "cannot write " + base + ".gp";
    return false;
  }
  if (!RunGnuplot({program, base + ".gp", base + ".log"}, error)) {
    *error += " (figure " + figure.name + ")";
    return false;
  }
  *svg = ReadText(base + ".svg");
  return true;
}

namespace {

bool IsNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

// At `i`, the start of an id's name: after "#" or "id='" (or "id=\"").
size_t IdNameAt(const std::string& s, size_t i) {
  if (s[i] == '#') return i + 1;
  if (s.compare(i, 3, "id=") == 0 && i + 3 < s.size() && (s[i + 3] == '\'' || s[i + 3] == '"'))
    return i + 4;
  return std::string::npos;
}

std::set<std::string> Ids(const std::string& s) {
  std::set<std::string> ids;
  for (size_t i = s.find("id="); i != std::string::npos; i = s.find("id=", i + 3)) {
    if (i + 3 >= s.size() || (s[i + 3] != '\'' && s[i + 3] != '"')) continue;
    const size_t end = s.find(s[i + 3], i + 4);
    if (end != std::string::npos) ids.insert(s.substr(i + 4, end - i - 4));
  }
  return ids;
}

}  // namespace

std::string InlineSvg(const std::string& svg, const std::string& id_prefix,
                      const std::string& label) {
  const size_t start = svg.find("<svg");
  if (start == std::string::npos) return "";
  const std::string s = svg.substr(start);
  const std::set<std::string> ids = Ids(s);
  std::string out;
  out.reserve(s.size() + 4096);
  for (size_t i = 0; i < s.size();) {
    const size_t name = IdNameAt(s, i);
    if (name == std::string::npos) {
      out += s[i++];
      continue;
    }
    size_t end = name;
    while (end < s.size() && IsNameChar(s[end])) ++end;
    out.append(s, i, name - i);
    if (ids.count(s.substr(name, end - name))) out += id_prefix;
    out.append(s, name, end - name);
    i = end;
  }
  out.insert(out.find("<svg") + 4, " role=\"img\" aria-label=\"" + EscapeHtml(label) + "\"");
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  return out;
}

}  // namespace ringid::html
