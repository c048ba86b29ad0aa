#include "hlsl/unity_versions.h"

#include <algorithm>
#include <array>

namespace kiln::hlsl {
namespace {

// Files of the three LTS lines' CGIncludes that one of them lacks (and Unity's UIElements layer,
// which 2019-2021 shipped beside them). Kiln's layer has the TextCore, colour-gamut and legacy
// texture-stack files; the others need Unity's own CGIncludes (-I).
constexpr std::array<VersionedFile, 11> kFiles = {{
    {"GraniteShaderLib3.cginc", kUnity2019, 0, false},
    {"TextCoreProperties.cginc", kUnity2019, 0, true},
    {"TextCore_Properties.cginc", kUnity2019, 0, true},
    {"TextCore_SDF_SSD.cginc", kUnity2019, 0, true},
    {"UnityColorGamut.cginc", kUnity2019, 0, true},
    {"UnityIndirect.cginc", kUnity2019, 0, false},
    {"UnityLegacyTextureStack.cginc", kUnity2019, 0, true},
    {"UnityRayTracingMeshUtils.cginc", kUnity2019, 0, false},
    {"UnityUIE.cginc", kUnity2019, 202130, false},
    {"UnityRayQuery.cginc", kUnity2023, 0, false},
    {"SpeedTreeShaderLibrary.cginc", kUnity2023, 0, false},
}};

std::string_view BaseName(std::string_view header) {
    const size_t slash = header.find_last_of("/\\");
    return slash == std::string_view::npos ? header : header.substr(slash + 1);
}

}  // namespace

const VersionedFile* FindVersionedFile(std::string_view header) {
    const std::string_view name = BaseName(header);
    const auto it = std::find_if(kFiles.begin(), kFiles.end(),
                                 [&](const VersionedFile& f) { return f.name == name; });
    return it == kFiles.end() ? nullptr : &*it;
}

bool UnityShips(std::string_view header, int version) {
    const VersionedFile* f = FindVersionedFile(header);
    return f == nullptr ||
           ((f->first == 0 || version >= f->first) && (f->last == 0 || version <= f->last));
}

std::string ReleaseName(int version) {
    const int major = version / 100, minor = (version / 10) % 10;
    return std::to_string(major) + "." + std::to_string(minor);
}

std::optional<std::string> MissingIncludeNote(std::string_view header, int version) {
    const VersionedFile* f = FindVersionedFile(header);
    if (f == nullptr)
        return std::nullopt;
    std::string releases = "Unity " + ReleaseName(f->first);
    releases += f->last == 0 ? " and later" : " to " + ReleaseName(f->last);
    if (!UnityShips(header, version)) {
        return "Unity " + ReleaseName(version) + " does not ship '" + std::string(f->name) + "' (" +
               releases + " do; --unity-version selects the release)";
    }
    return "'" + std::string(f->name) + "' is part of " + releases +
           ", not of Kiln's include layer: compile against Unity's own CGIncludes (-I) for it";
}

pack::Precision DefaultPrecision(int version) {
    return version < kUnity2019 ? pack::Precision::kRelaxed : pack::Precision::kFull;
}

}  // namespace kiln::hlsl
