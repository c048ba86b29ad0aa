// The variants Unity never builds unless a project uses them: its built-in pipeline strips the
// engine keywords of features no scene in the build has, with Graphics Settings at their defaults
// ("Lightmap Modes: Automatic", "Fog Modes: Automatic", "Instancing Variants: Strip Unused").
// Kiln's default profile is that stripping for a build with no scene (a plain `kiln compile`):
// no baked or realtime lightmaps, no fog, no material with GPU instancing on; Kiln's runtime asks
// for none of these keywords either. `--strict-variants` (VariantRequest::strict_variants) builds
// every declared combination instead; `--scene` builds what the scene looks up, so the profile
// does not apply there.
#ifndef KILN_VARIANTS_STRIP_PROFILE_H_
#define KILN_VARIANTS_STRIP_PROFILE_H_

#include <span>
#include <string_view>

namespace kiln::variants {

struct ProfileGroup {
    std::string_view setting;  // Unity's Graphics Settings entry, "Lightmap Modes: Automatic"
    std::span<const std::string_view> keywords;
};

// The groups of the default profile, in Graphics Settings order.
std::span<const ProfileGroup> DefaultStripProfile();

// The group of the default profile that strips `keyword`; null when the profile keeps it.
const ProfileGroup* StrippedByDefault(std::string_view keyword);

}  // namespace kiln::variants

#endif  // KILN_VARIANTS_STRIP_PROFILE_H_
