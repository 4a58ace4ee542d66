// A request to stop the fits that are running (Ctrl-C in the Python module):
// every Levenberg-Marquardt and simplex fit stops at its next iteration, as
// failed, so whatever runs them ends soon with nothing to rely on. Nothing
// in ringid requests it by itself; the command line ends the process instead
// (apps/interrupt.h).
#ifndef RINGID_ESTIMATION_INTERRUPT_H_
#define RINGID_ESTIMATION_INTERRUPT_H_

namespace ringid {

void RequestInterrupt();  // async-signal-safe: a signal handler may call it
void ClearInterrupt();
bool InterruptRequested();

}  // namespace ringid

#endif  // RINGID_ESTIMATION_INTERRUPT_H_
