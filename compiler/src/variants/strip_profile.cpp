#include "variants/strip_profile.h"

#include <algorithm>
#include <array>

namespace kiln::variants {
namespace {

// Unity manual, "Graphics settings: Shader stripping" and "Shader variant stripping": with no
// scene using lightmaps, the baked (LIGHTMAP_ON, DIRLIGHTMAP_COMBINED), realtime GI
// (DYNAMICLIGHTMAP_ON) and mixed-lighting (LIGHTMAP_SHADOW_MIXING: Subtractive,
// SHADOWS_SHADOWMASK: Shadowmask) variants; with no scene using fog, every fog mode; with no
// material enabling GPU instancing, the instanced variants.
constexpr std::array<std::string_view, 5> kLightmaps = {
    "LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED", "DYNAMICLIGHTMAP_ON", "LIGHTMAP_SHADOW_MIXING",
    "SHADOWS_SHADOWMASK"};
constexpr std::array<std::string_view, 3> kFog = {"FOG_LINEAR", "FOG_EXP", "FOG_EXP2"};
constexpr std::array<std::string_view, 2> kInstancing = {"INSTANCING_ON",
                                                         "PROCEDURAL_INSTANCING_ON"};

constexpr std::array<ProfileGroup, 3> kProfile = {{
    {"Lightmap Modes: Automatic", kLightmaps},
    {"Fog Modes: Automatic", kFog},
    {"Instancing Variants: Strip Unused", kInstancing},
}};

}  // namespace

std::span<const ProfileGroup> DefaultStripProfile() {
    return kProfile;
}

const ProfileGroup* StrippedByDefault(std::string_view keyword) {
    for (const ProfileGroup& g : kProfile) {
        if (std::find(g.keywords.begin(), g.keywords.end(), keyword) != g.keywords.end())
            return &g;
    }
    return nullptr;
}

}  // namespace kiln::variants
