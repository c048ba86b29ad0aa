// What differs between the Unity releases Kiln reproduces (--unity-version, 2018.4 to 6000.x),
// in one place: the include files each release ships, the precision its Vulkan back end gives
// `half` and `fixed`, and the names its layer declares (templates/ tests UNITY_VERSION against
// kUnity2019 for those). Verified against three LTS lines' CGIncludes (2018.4, 2022.3, 6000.0):
// a difference between two of them is placed at the first release after the older one (2019.1,
// 2023.1), and docs/unity-compat.md has the table.
#ifndef KILN_HLSL_UNITY_VERSIONS_H_
#define KILN_HLSL_UNITY_VERSIONS_H_

#include <optional>
#include <string>
#include <string_view>

#include "kiln/pack/format.h"

namespace kiln::hlsl {

// UNITY_VERSION numbers (2022.3 -> 202230) where the layer changes.
inline constexpr int kUnity2019 = 201910;
inline constexpr int kUnity2023 = 202310;

// A Unity include file that not every release ships.
struct VersionedFile {
    std::string_view name;
    int first = 0;               // first UNITY_VERSION that ships it (0: every release Kiln knows)
    int last = 0;                // last UNITY_VERSION that ships it (0: still shipped)
    bool in_kiln_layer = false;  // templates/ has it
};

// The entry for `header` (a file name, compared without its folder), if it is versioned.
const VersionedFile* FindVersionedFile(std::string_view header);

// Whether Unity release `version` ships `header`: false only for a versioned file outside its
// releases. Kiln's layer serves a file only where this holds.
bool UnityShips(std::string_view header, int version);

// "2019.1", "6000.0": a UNITY_VERSION number as Unity names the release.
std::string ReleaseName(int version);

// The note for a missing include of a versioned file under `version`, or none: which releases
// ship it, and whether Kiln's layer has it.
std::optional<std::string> MissingIncludeNote(std::string_view header, int version);

// What `half` and `fixed` are when --precision is not given: Unity 2018 made them min16float on
// every Vulkan target (RelaxedPrecision, Kiln's relaxed); later releases only on mobile Vulkan,
// 32-bit float on desktop (Kiln's full).
pack::Precision DefaultPrecision(int version);

}  // namespace kiln::hlsl

#endif  // KILN_HLSL_UNITY_VERSIONS_H_
