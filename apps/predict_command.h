// `ringid predict`: the modes of a parameter set, standing and at speeds,
// and where the lug orders meet them (operations/predict.h).
#ifndef RINGID_APPS_PREDICT_COMMAND_H_
#define RINGID_APPS_PREDICT_COMMAND_H_

namespace ringid {

int Predict(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_PREDICT_COMMAND_H_
