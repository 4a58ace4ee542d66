// Mode labels that do not depend on the guess: a UFF import labelled by the
// model at the user's parameters, fitted, and labelled again by the fitted
// model until the labels hold.
#ifndef RINGID_ESTIMATION_LABEL_BY_FIT_H_
#define RINGID_ESTIMATION_LABEL_BY_FIT_H_

#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "estimation/identify.h"

namespace ringid {

// The labels rest on a poor fit, and the import warns (UffImport::warnings),
// where the last labelling fit's chi-square p-value is below kPoorLabelFitP
// or a mode the model labelled by its shape has a MAC below kPoorLabelMac
// with the model mode that named it.
inline constexpr double kPoorLabelFitP = 1e-3;
inline constexpr double kPoorLabelMac = 0.8;

// UffToDataset at `guess`; where the model labelled modes (the map did not),
// the dataset is identified under `o` (measured shapes decide the pairing,
// contract §2; the starts and modes without a mapped shape go by label, so
// a round can fit differently) and labelled again at the fitted parameters,
// at most three rounds, until no label changes. The known and initial values
// stay the guess's. A fit that fails keeps the names of the round before,
// with a note. Shapes are compared under o.residuals.shape_convention. A
// poor labelling (kPoorLabelFitP, kPoorLabelMac) is a warning. False, with
// `error`, as UffToDataset, or where the dataset breaks the loader's rules
// (checked before it is fitted).
bool UffToDatasetLabelledByFit(const UffFile& file, const UffMap& map, const Parameters& guess,
                               const IdentifyOptions& o, UffImport* out, LoadError* error);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_LABEL_BY_FIT_H_
