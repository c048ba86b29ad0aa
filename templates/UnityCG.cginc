// UnityCG.cginc: space transforms and helpers with Unity's names, over Kiln's own functions.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityShaderUtilities.cginc"
#include "KilnCommon.cginc"
#include "KilnColor.cginc"
#include "KilnAttenuation.cginc"
#include "KilnSH.cginc"

#define UNITY_PI KILN_PI
#define UNITY_TWO_PI (2.0 * KILN_PI)
#define UNITY_HALF_PI (0.5 * KILN_PI)
#define UNITY_INV_PI KILN_INV_PI
#define HALF_MAX KILN_HALF_MAX

// ---- transforms ----

float4 UnityWorldToClipPos(float3 pos) {
    return mul(unity_MatrixVP, float4(pos, 1.0));
}

float3 UnityObjectToViewPos(float3 pos) {
    return mul(unity_MatrixV, mul(unity_ObjectToWorld, float4(pos, 1.0))).xyz;
}

// Normals transform with the inverse transpose of M: n_world = n * M^-1 (row vector), normalized.
float3 UnityObjectToWorldNormal(float3 norm) {
    // guard: a zero-length normal stays zero instead of becoming NaN
    return SafeNormalize(mul(norm, (float3x3)unity_WorldToObject));
}

float3 UnityObjectToWorldDir(float3 dir) {
    // guard: a zero direction stays zero
    return SafeNormalize(mul((float3x3)unity_ObjectToWorld, dir));
}

// Unnormalized direction from a world position to the camera.
float3 UnityWorldSpaceViewDir(float3 worldPos) {
    return _WorldSpaceCameraPos.xyz - worldPos;
}
float3 WorldSpaceViewDir(float4 objectPos) {
    return UnityWorldSpaceViewDir(mul(unity_ObjectToWorld, objectPos).xyz);
}

// Unnormalized direction to the light: the direction itself (w = 0) or position - p (w = 1).
float3 UnityWorldSpaceLightDir(float3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}
float3 WorldSpaceLightDir(float4 objectPos) {
    return UnityWorldSpaceLightDir(mul(unity_ObjectToWorld, objectPos).xyz);
}

// Clip-space position -> (x, y, w) for screen-space texture lookups at xy / w (Vulkan: y down).
float4 ComputeScreenPos(float4 clipPos) {
    float4 o = clipPos * 0.5;
    o.xy = float2(o.x, o.y) + o.w;
    o.zw = clipPos.zw;
    return o;
}

// Texture tiling and offset from the material's <name>_ST vector.
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)

// ---- normal maps ----

// Tangent-space normal from an RGB normal-map texel (glTF / OpenGL convention, +Y up).
float3 UnpackNormal(float4 packednormal) {
    // guard: a (0.5, 0.5, 0.5) or black texel decodes to zero length; SafeNormalize keeps it 0
    return SafeNormalize(packednormal.xyz * 2.0 - 1.0);
}

// Same with the material's bump scale applied to x and y (glTF normalTexture.scale).
float3 UnpackScaleNormal(float4 packednormal, float bumpScale) {
    float3 n = packednormal.xyz * 2.0 - 1.0;
    n.xy *= bumpScale;
    return SafeNormalize(n);
}

// Two-channel (DXT5nm / BC5) normal maps: x in a (or r), y in g, z reconstructed.
float3 UnpackNormalDXT5nm(float4 packednormal) {
    float3 n;
    n.xy = packednormal.wy * 2.0 - 1.0;
    // guard: |xy| > 1 after filtering would make sqrt's argument negative
    n.z = sqrt(saturate(1.0 - dot(n.xy, n.xy)));
    return n;
}

// ---- colour ----

float3 GammaToLinearSpace(float3 sRGB) {
    return SrgbToLinear(sRGB);
}
float3 LinearToGammaSpace(float3 linRGB) {
    return LinearToSrgb(linRGB);
}
float Luminance(float3 rgb) {
    return LuminanceRec709(rgb);
}

// ---- ambient and per-vertex lights ----

// Ambient irradiance / pi from the scene's SH probe for unit normal.xyz (normal.w is ignored;
// Unity requires it to be 1).
float3 ShadeSH9(float4 normal) {
    return SH_Irradiance(unity_SHAr, unity_SHAg, unity_SHAb, unity_SHBr, unity_SHBg, unity_SHBb,
                         unity_SHC, normal.xyz);
}

// Diffuse light of four point lights at a vertex, Lambert with the same inverse-square and
// range-window attenuation as pixel lights (KilnAttenuation.cginc), so a light moved between
// pixel and vertex lighting changes only in interpolation. lightAttenSq holds 1 / range^2.
float3 Shade4PointLights(float4 lightPosX, float4 lightPosY, float4 lightPosZ, float3 lightColor0,
                         float3 lightColor1, float3 lightColor2, float3 lightColor3,
                         float4 lightAttenSq, float3 pos, float3 normal) {
    float4 toLightX = lightPosX - pos.x;
    float4 toLightY = lightPosY - pos.y;
    float4 toLightZ = lightPosZ - pos.z;
    float4 lengthSq = toLightX * toLightX + toLightY * toLightY + toLightZ * toLightZ;
    float4 ndotl = toLightX * normal.x + toLightY * normal.y + toLightZ * normal.z;
    // guard: a vertex at a light's position has no direction to it; bound the length (1 cm)
    float4 safeLengthSq = max(lengthSq, KILN_MIN_LIGHT_DISTANCE * KILN_MIN_LIGHT_DISTANCE);
    ndotl = max(0.0, ndotl * rsqrt(safeLengthSq));
    float4 atten;
    atten.x = Attenuation_Distance(lengthSq.x, lightAttenSq.x);
    atten.y = Attenuation_Distance(lengthSq.y, lightAttenSq.y);
    atten.z = Attenuation_Distance(lengthSq.z, lightAttenSq.z);
    atten.w = Attenuation_Distance(lengthSq.w, lightAttenSq.w);
    float4 diff = ndotl * atten;
    return lightColor0 * diff.x + lightColor1 * diff.y + lightColor2 * diff.z +
           lightColor3 * diff.w;
}

#endif  // UNITY_CG_INCLUDED
