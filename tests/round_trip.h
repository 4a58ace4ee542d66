// A typed report written, read back and written again must be the same bytes.
#ifndef RINGID_TESTS_ROUND_TRIP_H_
#define RINGID_TESTS_ROUND_TRIP_H_

#include <string>

#include <gtest/gtest.h>

#include "report/report.h"

namespace ringid::testing {

// `text` read as a report R and written again; "" with `error` set when it
// does not read.
template <class R>
std::string ReadAndWriteAgain(const std::string& text, std::string* error) {
  R report;
  if (!ReadReport(Json::parse(text), &report, error)) return "";
  return ReportText(report);
}

template <class R>
void ExpectRoundTrip(const R& report) {
  const std::string written = ReportText(report);
  std::string error;
  EXPECT_EQ(ReadAndWriteAgain<R>(written, &error), written) << error;
}

}  // namespace ringid::testing

#endif  // RINGID_TESTS_ROUND_TRIP_H_
