// Names the compiler's Unity knowledge and the runtime's forward path must spell alike: the
// LightMode values Kiln's renderer draws (and the compiler's UNITY_PASS_* defines key on), and the
// engine keywords the renderer enables, which the compiler's multi_compile_fwdbase/_fwdadd
// shortcuts declare. Plain `const char*`, so they initialise std::string tables directly.
#ifndef KILN_PACK_ENGINE_NAMES_H_
#define KILN_PACK_ENGINE_NAMES_H_

namespace kiln::pack {

// The pass tag that says which pipeline step draws a pass.
inline constexpr const char* kTagLightMode = "LightMode";

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

}  // namespace kiln::pack

#endif  // KILN_PACK_ENGINE_NAMES_H_
