// Accuracy and conditioning suites, each a JSON report and a Markdown table.
#ifndef RINGID_BENCHMARKS_SUITES_H_
#define RINGID_BENCHMARKS_SUITES_H_

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "model/parameters.h"

namespace ringid {

struct SuiteOptions {
  std::string source_dir = ".";  // where datasets/ lives
  int replicates = 200;          // synthetic: Monte Carlo replicates per tire
  unsigned seed = 1;
  // Called with (done, total) as the suite's cases finish.
  std::function<void(int, int)> on_case;
};

struct SuiteResult {
  bool ok = false;
  std::string error;
  nlohmann::json report;
  std::string markdown;
};

// "paper", "synthetic" or "conditioning"; false in ok for an unknown name.
SuiteResult RunSuite(const std::string& name, const SuiteOptions& options);

// The paper's tire scaled by s: masses s^2, inertias s^4, lengths s,
// translational stiffness s, contact stiffness K (N) s^2, rotational
// stiffness s^3, dampings so that every damping ratio stays the same.
Parameters ScaledTire(const Parameters& paper, double s);

}  // namespace ringid

#endif  // RINGID_BENCHMARKS_SUITES_H_
