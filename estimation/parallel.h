// Work spread over threads; results are the same on any number of them.
#ifndef RINGID_ESTIMATION_PARALLEL_H_
#define RINGID_ESTIMATION_PARALLEL_H_

#include <functional>

namespace ringid {
namespace internal {

// The threads `threads` asks for: itself when positive, else one per core
// this process may run on (its affinity mask, as a batch scheduler sets it).
int ThreadsFor(int threads);

// Runs work(i) for every i in [0, n) on up to ThreadsFor(threads) threads,
// the calling one among them (fewer when the system has no more to give).
// work must only write what item i owns. The first exception work throws
// stops the items not yet begun and is rethrown once every thread is joined.
void ParallelFor(int n, int threads, const std::function<void(int)>& work);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_PARALLEL_H_
