// Shared fixtures: the paper's published numbers and synthetic datasets.
#ifndef RINGID_TESTS_TEST_SUPPORT_H_
#define RINGID_TESTS_TEST_SUPPORT_H_

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "model/parameters.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"

namespace ringid::testing {

std::string SourcePath(const std::string& relative);

// The public third-party corpora (.tir and UFF files) are read in place, never
// carried: from RINGID_CORPUS_DIR, by default ../shared/data beside the
// checkout. A test that reads them derives its fixture from CorpusTest and is
// named *CorpusTest: tests/CMakeLists.txt labels those `corpus` in ctest, and
// each skips, naming the directory, where the corpus is absent.
std::string CorpusDir();
std::string CorpusPath(const std::string& relative);  // CorpusDir() + "/" + relative
inline std::string UffCorpus(const std::string& name) { return CorpusPath("uff/" + name); }
class CorpusTest : public ::testing::Test {
 protected:
  void SetUp() override;
};
// Table 2 of the paper (with its ties), typed in from the paper
// (docs/model.md section 12).
Parameters Table2();
// Table 2 plus the inertias shipped in datasets/paper/parameters.json.
Parameters PaperIdentified();

// Each parameter of `effect` at a size that moves what it touches: a fifth
// of the element changed, a hub half as compliant as the sidewall, a coupling
// of 30 % of the geometric mean of the two sidewalls it joins.
Parameters WithEffectSized(const Effect& effect, Parameters p);

// datasets/synthetic.h's Simulate of all seven modes (shapes on the seven belt
// and rim degrees of freedom), with relative frequency and damping noise.
Dataset SyntheticDataset(const RigidRingModel& model, const Parameters& truth,
                         double freq_rel_sigma, double damping_rel_sigma,
                         double shape_sigma, std::mt19937_64* rng);

// Every field of the dataset of docs/conventions.md §3 broken in every way that makes
// sense, as file text; `field` is what the error line must name ("" for text
// that is not JSON at all).
struct MalformedDataset {
  std::string what;
  std::string text;
  std::string field;
};
std::vector<MalformedDataset> MalformedDatasets();

// The one line a dataset's text, read as `file`, is refused with; "" where it loads.
std::string DatasetErrorOf(const nlohmann::json& j, const std::string& file = "bad.json");
// A UFF file's and a UFF map's text, parsed; a failure fails the test.
UffFile ParsedUff(const std::string& text);  // read as test.uff
UffMap ParsedUffMap(const std::string& json);  // read as map.json

// The ringid executable, run with `args` (in directory `cwd` if given).
struct RunResult {
  int status;       // exit status, -1 when killed
  std::string err;  // what it wrote on stderr
  std::string out;  // and on stdout
};
RunResult Ringid(const std::string& args, const std::string& cwd = "");
// ringid `args`, started in the source tree and not waited for; stdout
// discarded, stderr to `err`.
int StartRingid(const std::string& args, const std::string& err);
// The exit status of the process `pid`, -1 if a signal killed it.
int WaitFor(int pid);
// A scratch path private to this test process: ctest runs tests in parallel.
std::string Scratch(const std::string& name);
bool Exists(const std::string& path);
std::string ReadFile(const std::string& path);

// Whether `program` is an executable on PATH.
bool HaveProgram(const std::string& program);
// Whether the tests run in CI (CI set and not "false" or "0"), where a
// missing tool is a failure, not a skip.
bool InCi();

}  // namespace ringid::testing

// In a test body: skips the test when `present` is false, or fails it in CI.
#define RINGID_REQUIRE_TOOL(present, tool)                                             \
  do {                                                                                 \
    if (!(present)) {                                                                  \
      if (::ringid::testing::InCi()) FAIL() << tool << " is missing, and CI needs it"; \
      GTEST_SKIP() << tool << " is not installed";                                     \
    }                                                                                  \
  } while (false)

#endif  // RINGID_TESTS_TEST_SUPPORT_H_
