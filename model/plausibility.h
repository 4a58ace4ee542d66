// Physical plausibility of a parameter set: typical ranges of rigid-ring tire
// parameters, for passenger-car to truck tires (docs/plausibility.md).
//
// A flag is a warning, never an error: a fitted set may be a good fit and still
// be unlike a tire (a value outside its typical range usually means the data
// did not determine it, or that the model lacks something).
#ifndef RINGID_MODEL_PLAUSIBILITY_H_
#define RINGID_MODEL_PLAUSIBILITY_H_

#include <functional>
#include <string>
#include <vector>

#include "model/parameters.h"

namespace ringid {

struct PlausibilityFlag {
  std::string rule;               // the rule's id, e.g. "loaded_radius_vs_rolling_radius"
  std::vector<Param> parameters;  // the parameters it concerns
  std::string reason;             // one sentence with the numbers

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("rule", &rule);
    a->Visit("parameters", &parameters);
    a->Visit("reason", &reason);
  }
};

// One row of the rule table.
struct PlausibilityRule {
  std::string id;
  std::vector<Param> parameters;  // all must be used and set for the rule to apply
  std::string range;              // the plausible range, as text
  std::string why;                // justification, with sources
  // The reason the set breaks the rule, or "" when it does not. Called only
  // with every one of `parameters` set.
  std::function<std::string(const Parameters&)> check;
};

// The rule table, defined once in plausibility.cc; lives for the program's life.
const std::vector<PlausibilityRule>& PlausibilityRules();

// Every rule of PlausibilityRules() whose parameters are all in `used` and set
// in `p`, and that `p` breaks; in table order.
std::vector<PlausibilityFlag> CheckPlausibility(const Parameters& p,
                                                const std::vector<Param>& used);

// The rules as a Markdown table (rule, parameters, range, why), as pasted into
// docs/plausibility.md. Ends with a newline.
std::string PlausibilityTableMarkdown();

// `x` to 3 significant digits: plain for 1e-3 <= |x| < 1e5 ("0.00258",
// "7670", "10300"), else "1.07e5", "2.5e-4".
std::string FormatSignificant3(double x);

}  // namespace ringid

#endif  // RINGID_MODEL_PLAUSIBILITY_H_
