// Ctrl-C (SIGINT) and SIGTERM: one line on stderr saying what was kept, then
// exit status 128 + the signal (130 for Ctrl-C, 143 for SIGTERM, as a shell
// reports a process the signal killed). Killed silently, a run leaves the
// user to guess whether the report on disk is this run's or an older one.
#ifndef RINGID_APPS_INTERRUPT_H_
#define RINGID_APPS_INTERRUPT_H_

#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace ringid {

// Installs the handlers (once, before any thread starts). The line is
// "ringid: interrupted (SIGINT): " and what was kept: nothing, or the files
// written whole (operations/files.h), or what the KeptNote in force says.
void ExitOnInterrupt();

// While held, an interruption waits: the files being written are finished
// (all of a group or none) before the process ends, and no temporary file is
// left behind (operations/files.h, HoldFileWrites). Recursive, so that one
// holder may write several groups.
std::unique_lock<std::recursive_mutex> HoldInterruption();

// While in scope, what an interruption says was kept, made from the files
// written so far (a campaign names its finished reports and the summary it
// did not write).
class KeptNote {
 public:
  using Describe = std::function<std::string(const std::vector<std::string>& written)>;
  explicit KeptNote(Describe describe);
  ~KeptNote();
  KeptNote(const KeptNote&) = delete;
  KeptNote& operator=(const KeptNote&) = delete;
};

}  // namespace ringid

#endif  // RINGID_APPS_INTERRUPT_H_
