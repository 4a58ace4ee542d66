// The one rule that pairs measured modes with model modes (docs/conventions.md
// §2): the residuals pair each condition's modes by it (estimation/residuals.cc),
// and a UFF import names by it the modes its map does not (datasets/uff_dataset.cc).
#ifndef RINGID_DATASETS_PAIRING_H_
#define RINGID_DATASETS_PAIRING_H_

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "datasets/measurement_options.h"
#include "model/modal.h"
#include "model/names.h"

namespace ringid::internal {

// A measured mode as the pairing sees it. `label` is none where it is not
// known (an imported mode the map does not name).
struct ModeToPair {
  double frequency_hz = 0;
  const std::vector<std::pair<Dof, double>>* shape = nullptr;  // null or empty: none measured
  std::optional<ModeLabel> label;
  // Where given, FrequencyScore measures the distance of the poles (an
  // extracted pole against the model's at the fit to the same FRFs).
  std::optional<double> damping_ratio;
  bool HasShape() const { return shape && !shape->empty(); }
};

// How a measured mode was paired (the steps of PairModes).
enum class PairedBy { kShape, kLabel, kFrequency };

// The score a measured shape pairs by: its MAC with the model mode's shape
// under `convention`.
double ShapeScore(const Mode& mode, const ModeToPair& measured, ShapeConvention convention);
// The score a mode without a shape pairs by: minus the log-frequency
// distance (with a damping ratio, of the complex poles: |log λ - log λ'|),
// less 100 where its label is known and the model mode lies in another plane.
double FrequencyScore(const Mode& mode, const ModeToPair& measured);

// Pairs each of `measured` with a distinct one of `modes` (`pairs`, indices
// into `modes`; `by`, how):
// 1. measured shapes by MAC (ShapeScore), one to one, the largest sum;
// 2. a known label with the free model mode of that label;
// 3. the rest with free model modes by FrequencyScore, the largest sum.
// False, with `why` one line (to which the caller may add where), when they
// cannot be paired: more shapes or modes than `modes`, a known label that no
// model mode has (its roots are real), a score not finite.
bool PairModes(const std::vector<ModeToPair>& measured, const std::vector<const Mode*>& modes,
               ShapeConvention convention, std::vector<int>* pairs, std::vector<PairedBy>* by,
               std::string* why);

}  // namespace ringid::internal

#endif  // RINGID_DATASETS_PAIRING_H_
