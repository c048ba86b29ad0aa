#include "kiln/pack/names.h"

#include <algorithm>
#include <cctype>

namespace kiln::pack {
namespace {

std::string Lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

}  // namespace

std::string ClosestName(std::string_view name, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = std::max<size_t>(1, name.size() / 3) + 1;
    const std::string a = Lower(name);
    for (const std::string& c : candidates) {
        // Levenshtein distance, one row.
        const std::string b = Lower(c);
        std::vector<size_t> row(b.size() + 1);
        for (size_t j = 0; j <= b.size(); ++j) {
            row[j] = j;
        }
        for (size_t i = 1; i <= a.size(); ++i) {
            size_t diagonal = row[0];
            row[0] = i;
            for (size_t j = 1; j <= b.size(); ++j) {
                const size_t up = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
                diagonal = up;
            }
        }
        if (row[b.size()] < best_distance) {
            best_distance = row[b.size()];
            best = c;
        }
    }
    return best;
}

const std::vector<std::string>& KnownLightModes() {
    static const std::vector<std::string> modes = {
        // Built-in render pipeline (Kiln's runtime draws ForwardBase, ForwardAdd and Always).
        "Always", "ForwardBase", "ForwardAdd", "Deferred", "ShadowCaster", "MotionVectors",
        "PrepassBase", "PrepassFinal", "Vertex", "VertexLMRGBM", "VertexLM", "Meta",
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
