// Names the compiler's Unity knowledge and the runtime's forward path must spell alike: the
// LightMode values Kiln's renderer draws (and the compiler's UNITY_PASS_* defines key on), the
// engine keywords the renderer enables, which the compiler's multi_compile_fwdbase/_fwdadd
// shortcuts declare, the built-in globals the renderer fills (which the compiler therefore does
// not ask to be Properties), and Unity's named default textures (which the compiler accepts in
// Properties and the renderer binds). Plain `const char*`, so they initialise std::string tables
// directly. The G-buffer layout joins them with the deferred path (issue 16).
#ifndef KILN_PACK_ENGINE_NAMES_H_
#define KILN_PACK_ENGINE_NAMES_H_

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <utility>

namespace kiln::pack {

// The pass tag that says which pipeline step draws a pass.
inline constexpr const char* kTagLightMode = "LightMode";

// The SubShader (or pass) tag that says when an object draws: Unity's render queue, a name with
// an optional +N / -N or a number. Queues above kRenderQueueTransparentAbove are transparent.
inline constexpr const char* kTagQueue = "Queue";
inline constexpr std::pair<const char*, int> kRenderQueues[] = {{"Background", 1000},
                                                                {"Geometry", 2000},
                                                                {"AlphaTest", 2450},
                                                                {"Transparent", 3000},
                                                                {"Overlay", 4000}};
inline constexpr int kRenderQueueTransparentAbove = 2500;

// LightMode tag values (the full list of known ones: KnownLightModes(), kiln/pack/names.h).
inline constexpr const char* kLightModeAlways = "Always";
inline constexpr const char* kLightModeForwardBase = "ForwardBase";
inline constexpr const char* kLightModeForwardAdd = "ForwardAdd";
inline constexpr const char* kLightModeDeferred = "Deferred";
inline constexpr const char* kLightModeShadowCaster = "ShadowCaster";
inline constexpr const char* kLightModeMeta = "Meta";
inline constexpr const char* kLightModePrepassBase = "PrepassBase";
inline constexpr const char* kLightModePrepassFinal = "PrepassFinal";
inline constexpr const char* kLightModeMotionVectors = "MotionVectors";

// Engine keywords of the forward path: the light type of a pass, ambient from light probes, the
// four per-vertex lights of a base pass.
inline constexpr const char* kKeywordDirectional = "DIRECTIONAL";
inline constexpr const char* kKeywordPoint = "POINT";
inline constexpr const char* kKeywordSpot = "SPOT";
inline constexpr const char* kKeywordPointCookie = "POINT_COOKIE";
inline constexpr const char* kKeywordDirectionalCookie = "DIRECTIONAL_COOKIE";
inline constexpr const char* kKeywordLightProbeSH = "LIGHTPROBE_SH";
inline constexpr const char* kKeywordVertexLight = "VERTEXLIGHT_ON";
// Shadows (docs/runtime.md, "Shadows"): the base pass of a shadowed main directional light asks
// for SHADOWS_SCREEN (a screen-space shadow texture); additive passes ask for SHADOWS_SCREEN,
// SHADOWS_DEPTH (spot: a depth map) or SHADOWS_CUBE (point: a depth cube) by light type, and
// SHADOWS_SOFT for filtered spot and point shadows; ShadowCaster passes are drawn with
// SHADOWS_DEPTH (directional, spot, the camera's depth) or SHADOWS_CUBE (point).
inline constexpr const char* kKeywordShadowsScreen = "SHADOWS_SCREEN";
inline constexpr const char* kKeywordShadowsDepth = "SHADOWS_DEPTH";
inline constexpr const char* kKeywordShadowsCube = "SHADOWS_CUBE";
inline constexpr const char* kKeywordShadowsSoft = "SHADOWS_SOFT";

// The deferred path's G-buffer normals in the octahedral encoding (URP's name; UnityGBuffer.cginc).
inline constexpr const char* kKeywordGBufferNormalsOct = "_GBUFFER_NORMALS_OCT";

// The shader the renderer maps a glTF metallic-roughness material onto (no sidecar .material).
inline constexpr const char* kShaderStandardMetallic = "Kiln/StandardMetallic";
// ... and a KHR_materials_unlit material (base colour x vertex colour, no lighting).
inline constexpr const char* kShaderUnlit = "Kiln/Unlit";
// The deferred path's light pass (materials/internal/DeferredShading.shader; Unity's name for its
// own): the first loaded pack that has a shader of this name provides it.
inline constexpr const char* kShaderDeferredShading = "Hidden/Internal-DeferredShading";
// The screen-space shadow collector (materials/internal/ScreenSpaceShadows.shader; Unity's name):
// a directional light's shadow map read at the camera depth's world positions into a screen
// texture, filtered with SHADOWS_SOFT.
inline constexpr const char* kShaderScreenSpaceShadows = "Hidden/Internal-ScreenSpaceShadows";
// kiln stability's grid harness (templates/stability/KilnStabilityGrid.shader), compiled when the
// command runs; kiln/tools/template_stability.h fills its properties.
inline constexpr const char* kShaderStabilityGrid = "Hidden/Kiln/StabilityGrid";
inline constexpr const char* kStabilityGridFile = "stability/KilnStabilityGrid.shader";
// Its passes, by Name: a ranged light's stencil mask and the light bounded by it. A replacement
// shader without them has every light drawn by its first pass.
inline constexpr const char* kPassDeferredLightMask = "LIGHT_MASK";
inline constexpr const char* kPassDeferredLightBounded = "LIGHT_BOUNDED";

// The deferred path's targets as the light pass samples them (Unity's names).
inline constexpr const char* kTextureGBuffer0 = "_CameraGBufferTexture0";
inline constexpr const char* kTextureGBuffer1 = "_CameraGBufferTexture1";
inline constexpr const char* kTextureGBuffer2 = "_CameraGBufferTexture2";
inline constexpr const char* kTextureCameraDepth = "_CameraDepthTexture";
// A shadowed light's map as its receivers sample it: the screen-space shadows (SHADOWS_SCREEN),
// a depth map (SHADOWS_DEPTH) or a depth cube (SHADOWS_CUBE); the collector samples the light's
// depth map by this name.
inline constexpr const char* kTextureShadowMap = "_ShadowMapTexture";
// What `GrabPass { }` copies the colour drawn so far into (a named GrabPass uses its own name).
inline constexpr const char* kTextureGrab = "_GrabTexture";

// Built-in globals the renderer fills per frame, light or draw that are not named unity_* or
// UNITY_* (every such name is the engine's too: IsEngineGlobal). docs/shader-library.md.
inline constexpr const char* kGlobalLightColor0 = "_LightColor0";
inline constexpr const char* kGlobalWorldSpaceLightPos0 = "_WorldSpaceLightPos0";
inline constexpr const char* kGlobalWorldSpaceCameraPos = "_WorldSpaceCameraPos";
inline constexpr const char* kGlobalTime = "_Time";
inline constexpr const char* kGlobalSinTime = "_SinTime";
inline constexpr const char* kGlobalCosTime = "_CosTime";
inline constexpr const char* kGlobalProjectionParams = "_ProjectionParams";
inline constexpr const char* kGlobalScreenParams = "_ScreenParams";
inline constexpr const char* kGlobalZBufferParams = "_ZBufferParams";
inline constexpr const char* kGlobalLightPositionRange = "_LightPositionRange";
// Shadows: (1 - strength, 0, fade scale, fade offset) and the depth cube's projection
// (-f/(f-n), -f n/(f-n), bias, 1) (UnityShadowLibrary.cginc).
inline constexpr const char* kGlobalLightShadowData = "_LightShadowData";
inline constexpr const char* kGlobalLightProjectionParams = "_LightProjectionParams";
// Unity sets these too; Kiln's renderer does not yet (cookies), and a shader reading them gets
// zero, as in Unity without that feature.
inline constexpr const char* kGlobalLightMatrix0 = "_LightMatrix0";
inline constexpr const char* kGlobalSpecColor = "_SpecColor";

// Older UnityShaderVariables.cginc (2018) names, which Unity's engine still sets: the camera's
// projection (UNITY_MATRIX_P), the ambient (UNITY_LIGHTMODEL_AMBIENT / 2), the transposed
// model-view matrix per draw (UNITY_MATRIX_T_MV), and the directional shadow cascades' view-depth
// splits (Kiln's one cascade covers the scene: near (0, inf, inf, inf), far all inf).
inline constexpr const char* kGlobalMatrixProjection = "glstate_matrix_projection";
inline constexpr const char* kGlobalLightModelAmbient = "glstate_lightmodel_ambient";
inline constexpr const char* kGlobalMatrixTransposeModelView0 =
    "glstate_matrix_transpose_modelview0";
inline constexpr const char* kGlobalLightSplitsNear = "_LightSplitsNear";
inline constexpr const char* kGlobalLightSplitsFar = "_LightSplitsFar";

// The meta pass's PBR-validation settings (UnityMetaPass.cginc), which Unity's editor sets for its
// validation views; Kiln's renderer leaves them zero (the meta pass draws no validation view).
inline constexpr const char* kGlobalsEditorValidation[] = {
    "_CheckPureMetal",           "_CheckAlbedo",        "_AlbedoCompareColor",
    "_AlbedoMinLuminance",       "_AlbedoMaxLuminance", "_AlbedoHueTolerance",
    "_AlbedoSaturationTolerance"};

// A render-state property Unity's UI system sets globally (`ZTest [unity_GUIZTestMode]` in the UI
// shaders): LessEqual (4) for a canvas in a scene, which is how Kiln's renderer draws.
inline constexpr const char* kStateGuiZTestMode = "unity_GUIZTestMode";
inline constexpr float kStateGuiZTestModeValue = 4;

inline constexpr const char* kEngineGlobals[] = {
    kGlobalLightColor0,
    kGlobalWorldSpaceLightPos0,
    kGlobalWorldSpaceCameraPos,
    kGlobalTime,
    kGlobalSinTime,
    kGlobalCosTime,
    kGlobalProjectionParams,
    kGlobalScreenParams,
    kGlobalZBufferParams,
    kGlobalLightPositionRange,
    kGlobalLightMatrix0,
    kGlobalLightShadowData,
    kGlobalLightProjectionParams,
    kGlobalSpecColor,
    kGlobalMatrixProjection,
    kGlobalLightModelAmbient,
    kGlobalMatrixTransposeModelView0,
    kGlobalLightSplitsNear,
    kGlobalLightSplitsFar,
    kTextureGBuffer0,
    kTextureGBuffer1,
    kTextureGBuffer2,
    kTextureCameraDepth,
    kTextureShadowMap,
    kTextureGrab,
};

// Whether the engine, not a material, sets the global `name` (an engine texture's
// <name>_TexelSize too).
constexpr bool IsEngineGlobal(std::string_view name) {
    if (name.substr(0, 6) == "unity_" || name.substr(0, 6) == "UNITY_") {
        return true;
    }
    constexpr std::string_view kTexelSize = "_TexelSize";
    if (name.size() > kTexelSize.size() &&
        name.substr(name.size() - kTexelSize.size()) == kTexelSize) {
        name = name.substr(0, name.size() - kTexelSize.size());
    }
    for (const char* g : kEngineGlobals) {
        if (name == g) {
            return true;
        }
    }
    for (const char* g : kGlobalsEditorValidation) {
        if (name == g) {
            return true;
        }
    }
    return false;
}

// Unity's named default textures for a texture property (`_MainTex ("Albedo", 2D) = "white" {}`)
// and the RGBA8 texel the renderer binds for each. An empty or unknown name is "gray".
struct DefaultTexture {
    const char* name;
    uint8_t rgba[4];
};
inline constexpr const char* kDefaultTextureBump = "bump";
inline constexpr const char* kDefaultTextureFallback = "gray";
inline constexpr DefaultTexture kDefaultTextures[] = {
    {"white", {255, 255, 255, 255}},
    {"black", {0, 0, 0, 0}},
    {"gray", {128, 128, 128, 128}},
    {"grey", {128, 128, 128, 128}},
    {"linearGray", {128, 128, 128, 128}},
    {kDefaultTextureBump, {128, 128, 255, 128}},  // a flat tangent-space normal
    {"red", {255, 0, 0, 255}},
};

// The default texture of that name, ignoring ASCII case ("White" is "white", as the ShaderLab
// check has always accepted); nullptr for a name Unity does not define.
constexpr const DefaultTexture* FindDefaultTexture(std::string_view name) {
    auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    for (const DefaultTexture& t : kDefaultTextures) {
        const std::string_view n = t.name;
        bool same = n.size() == name.size();
        for (size_t i = 0; same && i < n.size(); ++i) {
            same = lower(n[i]) == lower(name[i]);
        }
        if (same) {
            return &t;
        }
    }
    return nullptr;
}

}  // namespace kiln::pack

#endif  // KILN_PACK_ENGINE_NAMES_H_
