// Name suggestions shared by the compiler's and the runtime's diagnostics ("did you mean ...").
#ifndef KILN_PACK_NAMES_H_
#define KILN_PACK_NAMES_H_

#include <string>
#include <string_view>
#include <vector>

namespace kiln::pack {

// Edit distance suggestion: the candidate closest to `name` within a third of its length, or "".
// Case-insensitive Levenshtein distance.
std::string ClosestName(std::string_view name, const std::vector<std::string>& candidates);

// "; did you mean 'X'?" for the closest candidate, or "" when none is close: the one spelling of
// a suggestion appended to a diagnostic's message.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates);

// The LightMode tag values Unity's pipelines draw (built-in, URP, HDRP): a pass tagged otherwise
// is never drawn, so the compiler warns (K3013) with the closest of these.
const std::vector<std::string>& KnownLightModes();

}  // namespace kiln::pack

#endif  // KILN_PACK_NAMES_H_
