// The runtime's error value: one lower-case sentence naming what failed and where. Functions
// return std::optional<Error> (nullopt on success) and fill an out-parameter; nothing throws
// across the library boundary.
#ifndef KILN_RUNTIME_STATUS_H_
#define KILN_RUNTIME_STATUS_H_

#include <string>

namespace kiln::runtime {

// What kind of failure, for callers that report stable codes (the kiln CLI's K0xxx).
enum class ErrorKind {
    kFailed,          // the device, a pipeline, a file write: anything not below
    kScene,           // the scene or the frame settings ask for something that does not exist
    kMissingVariant,  // a pack lacks the variant a material needs
    kColor,           // an OpenColorIO config, display or view that does not exist
    kPack,            // a pack that cannot be read
};

struct Error {
    std::string message;
    ErrorKind kind = ErrorKind::kFailed;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_STATUS_H_
