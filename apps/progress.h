// Progress of a long run on stderr: "what: done/total, rate, time left".
// Silent unless stderr is a terminal, so JSON and logs never see it.
#ifndef RINGID_APPS_PROGRESS_H_
#define RINGID_APPS_PROGRESS_H_

#include <chrono>
#include <mutex>
#include <string>

namespace ringid {

class Progress {
 public:
  // `total` may be given later, by Set.
  explicit Progress(std::string what, int total = 0);
  ~Progress();  // ends the line
  // Thread-safe; redraw at most five times a second.
  void Add(int done = 1);
  void Set(int done, int total);

 private:
  void Changed();  // with mutex_ held
  void Draw(bool final);
  std::string what_;
  int total_, done_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mutex_;
};

}  // namespace ringid

#endif  // RINGID_APPS_PROGRESS_H_
