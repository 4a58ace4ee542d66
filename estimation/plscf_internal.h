// Internal to pLSCF (estimation/plscf.cc, estimation/plscf_poles.cc): the
// steps the refinement's changes to the set of physical poles share with the
// extraction.
#ifndef RINGID_ESTIMATION_PLSCF_INTERNAL_H_
#define RINGID_ESTIMATION_PLSCF_INTERNAL_H_

#include <vector>

#include "estimation/plscf.h"

namespace ringid::plscf_internal {

// The physical poles of a block's diagram in [low_hz, high_hz]: clusters of
// poles stable at min_stable_orders orders (in damping too where
// settled_damping), each at its highest order.
std::vector<ExtractedMode> ChoosePoles(const PlscfOptions& o, const std::vector<PlscfOrder>& diagram,
                                       double low_hz, double high_hz, bool settled_damping = true);
// A block's mode with its participation on all the Frf's inputs.
void OnAllInputs(const Frf& frf, const PlscfBlock& b, ExtractedMode* m);
// Two real poles are one where they lie within stable_frequency of `b`.
bool SameRealPole(const PlscfOptions& o, double a, double b);
// The physical real poles of a diagram (plscf.cc).
std::vector<double> ChooseRealPoles(const PlscfOptions& o, const std::vector<PlscfOrder>& diagram,
                                    double high_hz);
// Each mode's residues and its shape on the outputs.
void AddResidues(const Frf& frf, const std::vector<LsfdFunction>& functions,
                 std::vector<ExtractedMode>* modes);
// The modes and functions refined, in ascending frequency; untouched where
// the refinement fails.
void Refine(const Frf& frf, bool weigh_by_sigma, PlscfResult* r);
// Poles added where the refined model misses the FRFs (plscf_poles.cc).
void AddMissedPoles(const Frf& frf, const PlscfOptions& o, PlscfResult* r);
// Poles dropped where the data do not call for them (plscf_poles.cc).
void DropInsignificantPoles(const Frf& frf, const PlscfOptions& o, PlscfResult* r);

}  // namespace ringid::plscf_internal

#endif  // RINGID_ESTIMATION_PLSCF_INTERNAL_H_
