// What an operation says of bad input: the line the command line prints
// after "ringid: " (and exits 2 with), the file and field it names, and what
// is wrong. The Python module raises it as ringid.Error.
#ifndef RINGID_OPERATIONS_INPUT_ERROR_H_
#define RINGID_OPERATIONS_INPUT_ERROR_H_

#include <string>

#include "datasets/dataset.h"

namespace ringid {

struct InputError {
  std::string line;
  std::string file;     // the file read; "" for an option
  std::string field;    // the JSON path or key in it, or the option's name; "" where none
  std::string message;  // what is wrong with it

  // A file's error: its one line.
  static InputError Of(const LoadError& e) { return {e.OneLine(), e.file, e.field, e.message}; }
  // A line about the options: "--NAME: ..." names the option NAME.
  static InputError Option(const std::string& line) {
    std::string field;
    if (line.rfind("--", 0) == 0) field = line.substr(2, line.find(':') - 2);
    return {line, "", field, line};
  }
};

}  // namespace ringid

#endif  // RINGID_OPERATIONS_INPUT_ERROR_H_
