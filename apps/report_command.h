// `ringid report`: a report as one HTML page with its figures; `ringid
// export`: a parameter set as a .tir or ringid-parameters/1 (docs/tir.md).
#ifndef RINGID_APPS_REPORT_COMMAND_H_
#define RINGID_APPS_REPORT_COMMAND_H_

namespace ringid {

int ReportCommand(int argc, char** argv);
int ExportCommand(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_REPORT_COMMAND_H_
