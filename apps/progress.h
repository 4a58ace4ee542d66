// Progress of a long run on stderr: "what: done/total, rate, time left".
// Silent unless stderr is a terminal, so JSON and logs never see it.
#ifndef RINGID_APPS_PROGRESS_H_
#define RINGID_APPS_PROGRESS_H_

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ringid {

// A single run shows its progress once it has taken this long (a campaign,
// compare and bench from the start).
inline constexpr double kProgressAfterSeconds = 2;

class Progress {
 public:
  // `total` may be given later, by Set. With `after_seconds` > 0 nothing is
  // drawn before that time, and from then on the line is redrawn each
  // second (the elapsed time moves between steps); a run that ends sooner
  // leaves no trace.
  explicit Progress(std::string what, int total = 0, double after_seconds = 0);
  ~Progress();  // ends the line
  // Thread-safe; redraw at most five times a second.
  void Add(int done = 1);
  void Set(int done, int total);

 private:
  void Changed();  // with mutex_ held
  void Draw(bool final);
  void Tick();  // the redraws of a delayed progress
  std::string what_;
  int total_, done_ = 0;
  bool enabled_;
  bool drawn_ = false;  // a line is on the terminal
  bool stop_ = false;
  std::chrono::steady_clock::time_point start_, last_, quiet_until_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
};

}  // namespace ringid

#endif  // RINGID_APPS_PROGRESS_H_
