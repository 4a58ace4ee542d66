#include "apps/progress.h"

#include <unistd.h>

#include <cstdio>

namespace ringid {
namespace {

std::string Duration(double s) {
  char b[32];
  if (s >= 3600) std::snprintf(b, sizeof b, "%dh%02dm", int(s / 3600), int(s / 60) % 60);
  else if (s >= 60) std::snprintf(b, sizeof b, "%dm%02ds", int(s / 60), int(s) % 60);
  else std::snprintf(b, sizeof b, "%.0fs", s);
  return b;
}

}  // namespace

Progress::Progress(std::string what, int total, double after_seconds)
    : what_(std::move(what)), total_(total), enabled_(isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()), last_(start_),
      quiet_until_(start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(after_seconds))) {
  if (enabled_ && after_seconds > 0) ticker_ = std::thread([this] { Tick(); });
}

Progress::~Progress() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  const bool shown = std::chrono::steady_clock::now() >= quiet_until_ || drawn_;
  if (enabled_ && total_ > 0 && done_ > 0 && shown) Draw(true);
}

void Progress::Add(int done) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ += done;
  Changed();
}

void Progress::Set(int done, int total) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = done;
  total_ = total;
  Changed();
}

void Progress::Changed() {
  if (!enabled_ || total_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < quiet_until_) return;
  if (done_ < total_ && now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  Draw(false);
}

void Progress::Tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_until(lock, quiet_until_, [this] { return stop_; })) return;
  while (true) {
    if (total_ > 0) {
      last_ = std::chrono::steady_clock::now();
      Draw(false);
    }
    if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stop_; })) return;
  }
}

void Progress::Draw(bool final) {
  drawn_ = true;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = s > 0 ? done_ / s : 0;
  std::string line = what_ + ": " + std::to_string(done_) + "/" + std::to_string(total_);
  char b[64];
  std::snprintf(b, sizeof b, ", %.3g/s", rate);
  line += b;
  if (final) line += ", took " + Duration(s);
  else if (rate > 0) line += ", " + Duration((total_ - done_) / rate) + " left";
  else line += ", " + Duration(s) + " so far";
  std::fprintf(stderr, "\r\033[K%s%s", line.c_str(), final ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace ringid
