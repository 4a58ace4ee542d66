#include "estimation/parallel.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace ringid {
namespace internal {

int ThreadsFor(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void ParallelFor(int n, int threads, const std::function<void(int)>& work) {
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i; (i = next++) < n;) work(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(ThreadsFor(threads), n); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

}  // namespace internal
}  // namespace ringid
