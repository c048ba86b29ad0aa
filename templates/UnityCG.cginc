// UnityCG.cginc: Unity's general helpers (transforms, vertex structs, colour spaces, normal maps,
// encodings, depth, fog, shadow casters, ambient and vertex lights) with Unity's names and
// signatures, over Kiln's term files. Lighting conventions: docs/shader-library.md.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityShaderUtilities.cginc"
#include "UnityInstancing.cginc"
#include "KilnCommon.cginc"
#include "KilnColor.cginc"
#include "KilnAttenuation.cginc"
#include "KilnSH.cginc"
#include "KilnFog.cginc"
#include "KilnEncoding.cginc"

#define UNITY_PI KILN_PI
#define UNITY_TWO_PI (2.0 * KILN_PI)
#define UNITY_FOUR_PI (4.0 * KILN_PI)
#define UNITY_INV_PI KILN_INV_PI
#define UNITY_INV_TWO_PI (0.5 * KILN_INV_PI)
#define UNITY_INV_FOUR_PI (0.25 * KILN_INV_PI)
#define UNITY_HALF_PI (0.5 * KILN_PI)
#define UNITY_INV_HALF_PI (2.0 * KILN_INV_PI)
#define UNITY_HALF_MIN 6.103515625e-5  // smallest normal binary16 value
#define HALF_MAX KILN_HALF_MAX

// Kiln renders in linear colour space: these are the linear-space constants.
#define unity_ColorSpaceGrey float4(0.214041144, 0.214041144, 0.214041144, 0.5)
#define unity_ColorSpaceDouble float4(4.59479380, 4.59479380, 4.59479380, 2.0)
#define unity_ColorSpaceDielectricSpec float4(0.04, 0.04, 0.04, 1.0 - 0.04)
#define unity_ColorSpaceLuminance float4(0.2126, 0.7152, 0.0722, 1.0)  // ITU-R BT.709 weights

#define USING_LIGHT_MULTI_COMPILE
#define SCALED_NORMAL v.normal
#define EMISSIVE_RGBM_SCALE 97.0
#define LIGHTMAP_RGBM_SCALE 5.0
#define V2F_SCREEN_TYPE float4
#define API_HAS_GUARANTEED_R16_SUPPORT 0
#define UNITY_SHOULD_SAMPLE_SH \
    (defined(LIGHTPROBE_SH) && !defined(UNITY_PASS_FORWARDADD) && \
     !defined(UNITY_PASS_SHADOWCASTER) && !defined(UNITY_PASS_META))

// ---- vertex input structs ----
struct appdata_base {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tan {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_full {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    float4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// ---- colour spaces ----
inline bool IsGammaSpace() {
    return false;
}
inline float GammaToLinearSpaceExact(float value) {
    return SrgbToLinear(float3(value, value, value)).r;
}
inline float3 GammaToLinearSpace(float3 sRGB) {
    return SrgbToLinear(sRGB);
}
inline float LinearToGammaSpaceExact(float value) {
    return LinearToSrgb(float3(value, value, value)).r;
}
inline float3 LinearToGammaSpace(float3 linRGB) {
    return LinearToSrgb(linRGB);
}
inline float Luminance(float3 rgb) {
    return LuminanceRec709(rgb);
}
inline float LinearRgbToLuminance(float3 linearRgb) {
    return LuminanceRec709(linearRgb);
}

// ---- space transforms ----
inline float3 UnityObjectToViewPos(in float3 pos) {
    return mul(UNITY_MATRIX_V, mul(unity_ObjectToWorld, float4(pos, 1.0))).xyz;
}
inline float3 UnityObjectToViewPos(float4 pos) {
    return UnityObjectToViewPos(pos.xyz);
}
inline float3 UnityWorldToViewPos(in float3 pos) {
    return mul(UNITY_MATRIX_V, float4(pos, 1.0)).xyz;
}
inline float4 UnityWorldToClipPos(in float3 pos) {
    return mul(UNITY_MATRIX_VP, float4(pos, 1.0));
}
inline float4 UnityViewToClipPos(in float3 pos) {
    return mul(UNITY_MATRIX_P, float4(pos, 1.0));
}
inline float3 UnityObjectToWorldDir(in float3 dir) {
    // guard: a zero direction stays zero
    return SafeNormalize(mul((float3x3)unity_ObjectToWorld, dir));
}
inline float3 UnityWorldToObjectDir(in float3 dir) {
    return SafeNormalize(mul((float3x3)unity_WorldToObject, dir));
}
// Normals transform with the inverse transpose of M: n_world = n * M^-1 (row vector), normalized.
inline float3 UnityObjectToWorldNormal(in float3 norm) {
    // guard: a zero-length normal stays zero instead of becoming NaN
    return SafeNormalize(mul(norm, (float3x3)unity_WorldToObject));
}
// Unnormalized direction to the light: the direction itself (w = 0) or position - p (w = 1).
inline float3 UnityWorldSpaceLightDir(in float3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}
inline float3 WorldSpaceLightDir(in float4 localPos) {
    return UnityWorldSpaceLightDir(mul(unity_ObjectToWorld, localPos).xyz);
}
inline float3 ObjSpaceLightDir(in float4 v) {
    float3 objLight = mul(unity_WorldToObject, _WorldSpaceLightPos0).xyz;
    return objLight - v.xyz * _WorldSpaceLightPos0.w;
}
// Unnormalized direction from a point to the camera.
inline float3 UnityWorldSpaceViewDir(in float3 worldPos) {
    return _WorldSpaceCameraPos.xyz - worldPos;
}
inline float3 WorldSpaceViewDir(in float4 localPos) {
    return UnityWorldSpaceViewDir(mul(unity_ObjectToWorld, localPos).xyz);
}
inline float3 ObjSpaceViewDir(in float4 v) {
    float3 objCam = mul(unity_WorldToObject, float4(_WorldSpaceCameraPos.xyz, 1.0)).xyz;
    return objCam - v.xyz;
}

// The tangent-space rotation of an appdata_tan / appdata_full `v`: rows tangent, binormal, normal.
#define TANGENT_SPACE_ROTATION \
    float3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w; \
    float3x3 rotation = float3x3(v.tangent.xyz, binormal, v.normal)

// ---- ambient (spherical harmonics) ----
// The packing is in KilnSH.cginc; normal.w must be 1, as in Unity.
float3 SHEvalLinearL0L1(float4 normal) {
    return float3(SH_EvalL0L1(unity_SHAr, normal.xyz), SH_EvalL0L1(unity_SHAg, normal.xyz),
                  SH_EvalL0L1(unity_SHAb, normal.xyz));
}
float3 SHEvalLinearL2(float4 normal) {
    return float3(SH_EvalL2(unity_SHBr, unity_SHC.r, normal.xyz),
                  SH_EvalL2(unity_SHBg, unity_SHC.g, normal.xyz),
                  SH_EvalL2(unity_SHBb, unity_SHC.b, normal.xyz));
}
// Ambient irradiance / pi for a unit world normal (normal.w = 1).
float3 ShadeSH9(float4 normal) {
    return SH_Irradiance(unity_SHAr, unity_SHAg, unity_SHAb, unity_SHBr, unity_SHBg, unity_SHBb,
                         unity_SHC, normal.xyz);
}
// The L0 + L1 bands only (Unity's "third order" name for them).
float3 ShadeSH3Order(float4 normal) {
    return max(SHEvalLinearL2(normal), 0.0);
}
float3 ShadeSH12Order(float4 normal) {
    return max(SHEvalLinearL0L1(normal), 0.0);
}
#if UNITY_LIGHT_PROBE_PROXY_VOLUME
// The L0 + L1 bands from a light probe proxy volume (a 3D texture of three coefficient slices).
float3 SHEvalLinearL0L1_SampleProbeVolume(float4 normal, float3 worldPos) {
    const float transformToLocal = unity_ProbeVolumeParams.y;
    const float texelSizeX = unity_ProbeVolumeParams.z;
    float3 position = (transformToLocal == 1.0f)
                          ? mul(unity_ProbeVolumeWorldToObject, float4(worldPos, 1.0)).xyz
                          : worldPos;
    float3 coord = (position - unity_ProbeVolumeMin.xyz) * unity_ProbeVolumeSizeInv.xyz;
    coord.x = coord.x * 0.25f;
    float texCoordX = clamp(coord.x, 0.5f * texelSizeX, 0.25f - 0.5f * texelSizeX);
    float4 shAr = UNITY_SAMPLE_TEX3D_SAMPLER(unity_ProbeVolumeSH, unity_ProbeVolumeSH,
                                             float3(texCoordX, coord.yz));
    float4 shAg = UNITY_SAMPLE_TEX3D_SAMPLER(unity_ProbeVolumeSH, unity_ProbeVolumeSH,
                                             float3(texCoordX + 0.25f, coord.yz));
    float4 shAb = UNITY_SAMPLE_TEX3D_SAMPLER(unity_ProbeVolumeSH, unity_ProbeVolumeSH,
                                             float3(texCoordX + 0.5f, coord.yz));
    return float3(dot(shAr, normal), dot(shAg, normal), dot(shAb, normal));
}
#endif

// ---- per-vertex lights ----
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
    // guard: a colour near the float limit times an attenuation above 1 is +Inf at the vertex,
    // and interpolating Inf gives NaN across the triangle (kiln stability); clamp to binary16
    return ClampToHalfRange(lightColor0 * diff.x + lightColor1 * diff.y + lightColor2 * diff.z +
                            lightColor3 * diff.w);
}

// The legacy "Vertex" pass lights (view space, unity_LightPosition and unity_LightAtten) on a
// vertex: ambient plus Lambert with quadratic attenuation and, optionally, the spot cone.
float3 ShadeVertexLightsFull(float4 vertex, float3 normal, int lightCount, bool spotLight) {
    float3 viewPos = UnityObjectToViewPos(vertex.xyz);
    // guard: a zero normal stays zero
    float3 viewN = SafeNormalize(mul((float3x3)UNITY_MATRIX_IT_MV, normal));
    float3 lightColor = UNITY_LIGHTMODEL_AMBIENT.xyz;
    for (int i = 0; i < lightCount; i++) {
        float3 toLight = unity_LightPosition[i].xyz - viewPos.xyz * unity_LightPosition[i].w;
        float lengthSq = dot(toLight, toLight);
        // guard: a vertex at the light's position has no direction to it
        lengthSq = max(lengthSq, 0.000001);
        toLight *= rsqrt(lengthSq);
        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
        if (spotLight) {
            float rho = max(0, dot(toLight, unity_SpotDirection[i].xyz));
            atten *= saturate((rho - unity_LightAtten[i].x) * unity_LightAtten[i].y);
        }
        lightColor += unity_LightColor[i].rgb * (max(0, dot(viewN, toLight)) * atten);
    }
    return lightColor;
}
float3 ShadeVertexLights(float4 vertex, float3 normal) {
    return ShadeVertexLightsFull(vertex, normal, 4, false);
}

// Vertex-lit output and its fragment colour (texture times diffuse, plus specular).
struct v2f_vertex_lit {
    float2 uv : TEXCOORD0;
    fixed4 diff : COLOR0;
    fixed4 spec : COLOR1;
};
inline fixed4 VertexLight(v2f_vertex_lit i, sampler2D mainTex) {
    fixed4 texcol = tex2D(mainTex, i.uv);
    fixed4 c;
    c.xyz = (texcol.xyz * i.diff.xyz + i.spec.xyz * texcol.a);
    c.w = texcol.w * i.diff.w;
    return c;
}

// ---- textures ----
// Texture tiling and offset from the material's <name>_ST vector.
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)
#define TRANSFORM_UV(idx) v.texcoord.xy

inline float2 MultiplyUV(float4x4 mat, float2 inUV) {
    return mul(mat, float4(inUV, 0, 1)).xy;
}

// Parallax occlusion offset of the UV for a height sample h in [0, 1] (Kaneko et al. 2001 with
// Welsh's offset limiting: the view direction's z is biased by 0.42).
inline float2 ParallaxOffset(half h, half height, half3 viewDir) {
    h = h * height - height / 2.0;
    float3 v = SafeNormalize(viewDir);
    v.z += 0.42;
    return h * (v.xy / v.z);
}

// ---- encodings (KilnEncoding.cginc) ----
inline float4 EncodeFloatRGBA(float v) {
    return Encode_FloatRGBA(v);
}
inline float DecodeFloatRGBA(float4 enc) {
    return Decode_FloatRGBA(enc);
}
inline float2 EncodeFloatRG(float v) {
    return Encode_FloatRG(v);
}
inline float DecodeFloatRG(float2 enc) {
    return Decode_FloatRG(enc);
}
inline float2 EncodeViewNormalStereo(float3 n) {
    return Encode_ViewNormalStereo(n);
}
inline float3 DecodeViewNormalStereo(float4 enc4) {
    return Decode_ViewNormalStereo(enc4.xy);
}
inline float4 EncodeDepthNormal(float depth, float3 normal) {
    return float4(EncodeViewNormalStereo(normal), EncodeFloatRG(depth));
}
inline void DecodeDepthNormal(float4 enc, out float depth, out float3 normal) {
    depth = DecodeFloatRG(enc.zw);
    normal = DecodeViewNormalStereo(enc);
}

// HDR colour of a texture whose decode instructions are x = range, y = exponent, w = use alpha.
inline half3 DecodeHDR(half4 data, half4 decodeInstructions) {
    return Decode_RGBM(data, decodeInstructions);
}
// The same where the colour space is chosen at run time (the editor's previews).
inline half3 DecodeHDR(half4 data, half4 decodeInstructions, int colorspaceIsGamma) {
    half3 c = DecodeHDR(data, decodeInstructions);
    return colorspaceIsGamma ? LinearToGammaSpace(c) : c;
}
inline half3 DecodeLightmapRGBM(half4 data, half4 decodeInstructions) {
    return Decode_RGBM(data, decodeInstructions);
}
inline half3 DecodeLightmapDoubleLDR(fixed4 color, half4 decodeInstructions) {
    return Decode_DoubleLDR(color, decodeInstructions.x);
}
inline half3 DecodeLightmap(fixed4 color, half4 decodeInstructions) {
#if defined(UNITY_LIGHTMAP_DLDR_ENCODING)
    return DecodeLightmapDoubleLDR(color, decodeInstructions);
#elif defined(UNITY_LIGHTMAP_RGBM_ENCODING)
    return DecodeLightmapRGBM(color, decodeInstructions);
#else
    return color.rgb;  // full HDR
#endif
}
inline half3 DecodeLightmap(fixed4 color) {
    return DecodeLightmap(color, unity_Lightmap_HDR);
}
inline half3 DecodeRealtimeLightmap(fixed4 color) {
    return color.rgb;  // realtime GI lightmaps are stored linear, full range
}
// Directional lightmap: half-Lambert with the dominant direction in xyz (w rebalances).
inline half3 DecodeDirectionalLightmap(half3 color, fixed4 dirTex, half3 normalWorld) {
    half halfLambert = dot(normalWorld, dirTex.xyz - 0.5) + 0.5;
    // guard: a zero w would divide by zero
    return color * halfLambert / max(1e-4, dirTex.w);
}
inline half4 UnityEncodeRGBM(half3 color, float maxRGBM) {
    return Encode_RGBM(color, maxRGBM);
}

// ---- normal maps ----
// Two-channel (DXT5nm / BC5) normal maps: x in a, y in g, z reconstructed.
inline fixed3 UnpackNormalDXT5nm(fixed4 packednormal) {
    fixed3 normal;
    normal.xy = packednormal.wy * 2 - 1;
    // guard: |xy| > 1 after filtering would make sqrt's argument negative
    normal.z = sqrt(saturate(1 - dot(normal.xy, normal.xy)));
    return normal;
}
// Unity's desktop decoding, which reads DXT5nm (AG) and RGB maps alike: x = r * a, y = g.
inline fixed3 UnpackNormalmapRGorAG(fixed4 packednormal) {
    packednormal.x *= packednormal.w;
    fixed3 normal;
    normal.xy = packednormal.xy * 2 - 1;
    normal.z = sqrt(saturate(1 - dot(normal.xy, normal.xy)));
    return normal;
}
// Tangent-space normal from an RGB normal-map texel (glTF / OpenGL convention, +Y up): Kiln's
// runtime uploads normal maps as RGB, so all three channels are read (docs/unity-compat.md).
inline fixed3 UnpackNormal(fixed4 packednormal) {
    // guard: a (0.5, 0.5, 0.5) or black texel decodes to zero length; SafeNormalize keeps it 0
    return SafeNormalize(packednormal.xyz * 2.0 - 1.0);
}
// Same with the material's bump scale applied to x and y (glTF normalTexture.scale).
inline fixed3 UnpackNormalWithScale(fixed4 packednormal, float scale) {
    float3 n = packednormal.xyz * 2.0 - 1.0;
    n.xy *= scale;
    return SafeNormalize(n);
}

// Heightmaps in two 8-bit channels where 16-bit formats are not guaranteed (Vulkan).
float4 PackHeightmap(float height) {
    uint a = (uint)(65535.0f * saturate(height));
    return float4((a >> 0) & 0xFF, (a >> 8) & 0xFF, 0, 0) / 255.0f;
}
float UnpackHeightmap(float4 height) {
    return (height.r + height.g * 256.0f) / 257.0f;
}

// ---- depth ----
inline float Linear01Depth(float z) {
    return Depth_Linear01(z, _ZBufferParams);
}
inline float LinearEyeDepth(float z) {
    return Depth_LinearEye(z, _ZBufferParams);
}
#define COMPUTE_EYEDEPTH(o) o = -UnityObjectToViewPos(v.vertex).z
#define COMPUTE_DEPTH_01 -(UnityObjectToViewPos(v.vertex).z * _ProjectionParams.w)
#define COMPUTE_VIEW_NORMAL normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal))
#define DECODE_EYEDEPTH(i) LinearEyeDepth(i)
#define UNITY_TRANSFER_DEPTH(oo)
#define UNITY_OUTPUT_DEPTH(i) return 0

// ---- screen positions ----
// Clip-space position -> (x, y, w) for screen-space texture lookups at xy / w.
inline float4 ComputeNonStereoScreenPos(float4 pos) {
    float4 o = pos * 0.5f;
    o.xy = float2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}
inline float4 ComputeScreenPos(float4 pos) {
    return ComputeNonStereoScreenPos(pos);
}
// A GrabPass texture's row 0 is the top of the frame (as Unity's where UNITY_UV_STARTS_AT_TOP),
// while clip-space +y is up: y flips.
inline float4 ComputeGrabScreenPos(float4 pos) {
    float4 o = pos * 0.5f;
    o.xy = float2(o.x, -o.y) + o.w;
    o.zw = pos.zw;
    return o;
}
// Snaps a clip-space vertex to the pixel grid (for pixel-perfect sprites).
inline float4 UnityPixelSnap(float4 pos) {
    float2 hpc = _ScreenParams.xy * 0.5f;
    float2 pixelPos = round((pos.xy / pos.w) * hpc);
    pos.xy = pixelPos / hpc * pos.w;
    return pos;
}
inline float2 TransformViewToProjection(float2 v) {
    return mul((float2x2)UNITY_MATRIX_P, v);
}
inline float3 TransformViewToProjection(float3 v) {
    return mul((float3x3)UNITY_MATRIX_P, v);
}
// Mono rendering: the stereo adjustments are the identity.
inline float2 UnityStereoScreenSpaceUVAdjustInternal(float2 uv, float4 scaleAndOffset) {
    return uv.xy * scaleAndOffset.xy + scaleAndOffset.zw;
}
inline float4 UnityStereoScreenSpaceUVAdjustInternal(float4 uv, float4 scaleAndOffset) {
    return float4(UnityStereoScreenSpaceUVAdjustInternal(uv.xy, scaleAndOffset),
                  UnityStereoScreenSpaceUVAdjustInternal(uv.zw, scaleAndOffset));
}
#define UnityStereoScreenSpaceUVAdjust(x, y) (x)
#define UnityStereoTransformScreenSpaceTex(uv) (uv)
#define TransformStereoScreenSpaceTex(uv, w) (uv)
#define UnityStereoClamp(uv, scaleAndOffset) (uv)

// ---- minimal image-effect vertex shader ----
struct appdata_img {
    float4 vertex : POSITION;
    half2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct v2f_img {
    float4 pos : SV_POSITION;
    half2 uv : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};
v2f_img vert_img(appdata_img v) {
    v2f_img o;
    UNITY_INITIALIZE_OUTPUT(v2f_img, o);
    UNITY_SETUP_INSTANCE_ID(v);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    return o;
}

#include "UnityCGShadowCaster.cginc"
#include "UnityCGFog.cginc"

#endif  // UNITY_CG_INCLUDED
