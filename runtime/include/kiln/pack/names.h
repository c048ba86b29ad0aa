// Name suggestions shared by the compiler's and the runtime's diagnostics ("did you mean ...").
#ifndef KILN_PACK_NAMES_H_
#define KILN_PACK_NAMES_H_

#include <string>
#include <string_view>
#include <vector>

#include "kiln/base/text.h"

namespace kiln::pack {

// The name suggestions ("did you mean ...") live in base/text.h, below the pack format.
using base::ClosestName;
using base::DidYouMean;

// The LightMode tag values Unity's pipelines draw (built-in, URP, HDRP): a pass tagged otherwise
// is never drawn, so the compiler warns (K3013) with the closest of these.
const std::vector<std::string>& KnownLightModes();

}  // namespace kiln::pack

#endif  // KILN_PACK_NAMES_H_
