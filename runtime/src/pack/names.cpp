#include "kiln/pack/names.h"

#include "kiln/pack/engine_names.h"

namespace kiln::pack {

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

}  // namespace kiln::pack
