// docs/reference.md: the names a dataset and a parameter set use (parameters,
// degrees of freedom, labels, effects), drawn from the library's own tables
// (`ringid reference`).
#ifndef RINGID_APPS_REFERENCE_DOC_H_
#define RINGID_APPS_REFERENCE_DOC_H_

#include <string>

namespace ringid {

std::string ReferenceMarkdown();

}  // namespace ringid

#endif  // RINGID_APPS_REFERENCE_DOC_H_
