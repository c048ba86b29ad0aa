// The runtime's error value: one lower-case sentence naming what failed and where. Functions
// return std::optional<Error> (nullopt on success) and fill an out-parameter; nothing throws
// across the library boundary.
#ifndef KILN_RUNTIME_STATUS_H_
#define KILN_RUNTIME_STATUS_H_

#include <string>

namespace kiln::runtime {

struct Error {
    std::string message;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_STATUS_H_
