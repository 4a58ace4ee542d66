// What the model needs of a parameter set, and the one error for what it
// lacks: predict, simulate and forces all ask it.
#ifndef RINGID_OPERATIONS_MODEL_PARAMETERS_H_
#define RINGID_OPERATIONS_MODEL_PARAMETERS_H_

#include <string>
#include <vector>

#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "operations/input_error.h"
#include "operations/options.h"

namespace ringid {

// The effect of the catalogue that `p` belongs to, or null for a parameter
// of the baseline.
const Effect* EffectOwning(Param p);
// The parameters of `model` that `p` does not set, in the model's order.
std::vector<Param> Missing(const RigidRingModel& model, const Parameters& p);
// The error for the parameters the model needs and neither `source` (a
// parameter set, a dataset or a .tir) nor --set gives, `missing` in the
// model's order: the first named, with where it could come from, as the
// file's field (a .tir's: its name) or as --effects.
InputError MissingParameters(const std::string& source, const std::vector<Param>& missing,
                             const std::vector<std::string>& notes = {});
// simulate: every effect of `effects` has a size (non-zero, from `set`, the
// parameter file or `shift`) and every effect size in `set` has its effect
// in `effects`; `shift` in (0, 0.5) sizes the one effect.
bool CheckEffectSizes(const std::vector<const Effect*>& effects, const ParameterValues& set,
                      const Parameters& file, double shift, std::string* error);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_MODEL_PARAMETERS_H_
