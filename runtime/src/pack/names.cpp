#include "kiln/pack/names.h"

#include <algorithm>
#include <cctype>

#include "kiln/base/text.h"
#include "kiln/pack/engine_names.h"

namespace kiln::pack {
namespace {

using base::ToLower;

// Optimal string alignment distance: Levenshtein plus the swap of two adjacent characters as one
// edit (the commonest typo: ZWirte, _Tnit).
size_t Distance(const std::string& a, const std::string& b) {
    const size_t w = b.size() + 1;
    std::vector<size_t> d((a.size() + 1) * w);
    for (size_t i = 0; i <= a.size(); ++i)
        d[i * w] = i;
    for (size_t j = 0; j <= b.size(); ++j)
        d[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t cost = a[i - 1] != b[j - 1];
            size_t v = std::min(
                {d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                v = std::min(v, d[(i - 2) * w + j - 2] + 1);
            d[i * w + j] = v;
        }
    }
    return d[a.size() * w + b.size()];
}

}  // namespace

std::string ClosestName(std::string_view name, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = std::max<size_t>(1, name.size() / 3) + 1;
    const std::string a = ToLower(name);
    for (const std::string& c : candidates) {
        const size_t d = Distance(a, ToLower(c));
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

const std::vector<std::string>& KnownLightModes() {
    static const std::vector<std::string> modes = {
        // Built-in render pipeline (Kiln's runtime draws ForwardBase, ForwardAdd and Always).
        kLightModeAlways, kLightModeForwardBase, kLightModeForwardAdd, kLightModeDeferred,
        kLightModeShadowCaster, kLightModeMotionVectors, kLightModePrepassBase,
        kLightModePrepassFinal, "Vertex", "VertexLMRGBM", "VertexLM", kLightModeMeta,
        "GrabPass",  // Unity's own built-in shaders tag passes so (Internal-*)
        // Scriptable pipelines.
        "SRPDefaultUnlit", "UniversalForward", "UniversalForwardOnly", "UniversalGBuffer",
        "Universal2D", "DepthOnly", "DepthNormals", "DepthNormalsOnly", "GBuffer", "Forward",
        "ForwardOnly", "DepthForwardOnly", "TransparentDepthPrepass", "TransparentDepthPostpass",
        "TransparentBackface", "DistortionVectors", "FullScreenDebug", "Picking",
        "SceneSelectionPass"};
    return modes;
}

std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    const std::string near = ClosestName(name, candidates);
    return near.empty() ? std::string() : "; did you mean '" + near + "'?";
}

}  // namespace kiln::pack
