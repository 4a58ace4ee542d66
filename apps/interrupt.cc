#include "apps/interrupt.h"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>

#include "operations/files.h"

namespace ringid {
namespace {

// Never destroyed: the watcher may run while static objects are torn down.
// The files written and their lock are the library's (operations/files.h).
struct State {
  KeptNote::Describe describe;
};
State& Shared() {
  static State* state = new State;
  return *state;
}

int signal_pipe[2] = {-1, -1};

// Only what is async-signal-safe: the byte wakes the watcher.
void OnSignal(int signo) {
  const unsigned char byte = static_cast<unsigned char>(signo);
  [[maybe_unused]] const ssize_t n = ::write(signal_pipe[1], &byte, 1);
}

std::string Kept(const std::vector<std::string>& written) {
  if (written.empty()) return "nothing written (a report is written whole when its run ends)";
  std::string files;
  for (const std::string& f : written) files += (files.empty() ? "" : ", ") + f;
  return "kept " + std::to_string(written.size()) + " file(s) written whole before it: " + files;
}

// Waits for a signal, then for any write in progress, says what was kept and
// ends the process without running anything else (the run's state is
// whatever the interrupted threads left).
void Watch() {
  unsigned char signo = 0;
  while (::read(signal_pipe[0], &signo, 1) != 1) {
  }
  State& s = Shared();
  HoldFileWrites().release();  // never released: the process ends here
  const std::string kept = s.describe ? s.describe(FilesWritten()) : Kept(FilesWritten());
  const std::string line = std::string(isatty(STDERR_FILENO) ? "\r\033[K" : "") +
                           "ringid: interrupted (" + (signo == SIGINT ? "SIGINT" : "SIGTERM") +
                           "): " + kept + "\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + signo);
}

}  // namespace

void ExitOnInterrupt() {
  // Close-on-exec, so that gnuplot and other children do not hold it.
  if (::pipe2(signal_pipe, O_CLOEXEC) != 0) return;  // then the default action stays
  ::fcntl(signal_pipe[1], F_SETFL, O_NONBLOCK);      // a handler never blocks
  std::thread(Watch).detach();
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int signo : {SIGINT, SIGTERM}) ::sigaction(signo, &action, nullptr);
}

std::unique_lock<std::recursive_mutex> HoldInterruption() { return HoldFileWrites(); }

KeptNote::KeptNote(Describe describe) {
  const auto hold = HoldInterruption();
  Shared().describe = std::move(describe);
}

KeptNote::~KeptNote() {
  const auto hold = HoldInterruption();
  Shared().describe = nullptr;
}

}  // namespace ringid
