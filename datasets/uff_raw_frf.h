// A UFF file's FRFs (dataset 58, function type 4) as they are, without a map
// onto a model: each response and reference named by its node and direction
// ("101:+3", as `import --uff` lists them), each set of lines a condition of
// its own. What `ringid poles` reads (operations/poles.h).
#ifndef RINGID_DATASETS_UFF_RAW_FRF_H_
#define RINGID_DATASETS_UFF_RAW_FRF_H_

#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/frf.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"

namespace ringid {

// A node and direction of the file (direction +-1..6).
struct UffEnd {
  int node = 0, direction = 0;
};

// One set of lines: its FRFs, the node and direction of each output and
// input, and the units the values are in.
struct UffRawCondition {
  Frf frf;
  std::vector<UffEnd> outputs, inputs;
  // "SI (m/s² per N)" where the file's or the map's units say; else
  // "the file's units".
  std::string units;
};

struct UffRawFrfs {
  std::vector<UffRawCondition> conditions;
  std::vector<std::string> notes;  // what was left out or assumed
};

// The FRFs of `file`. `map` (may be null) gives the units and the averages
// behind coherence functions (type 6), which then give sigma; its points and
// labels are not used. Without it, or where a function's units do not say,
// values stay in the file's units (poles do not depend on them). Lines at or
// below 0 Hz, and FRFs that are zero at every line, are left out with a note. False, with `error` naming the record:
// no FRF in the file (time records, type 1, are not FRFs), an FRF that is
// not complex, lines that do not increase, fewer than `min_lines` lines above
// 0 Hz, every FRF zero.
bool ReadUffRawFrfs(const UffFile& file, const UffMap* map, int min_lines, UffRawFrfs* out,
                    LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_UFF_RAW_FRF_H_
