// UnityBuiltin3xTreeLibrary.cginc: Unity 3's tree (Tree Creator) leaf and bark helpers with
// Unity's names: translucent leaf lighting (wrapped diffuse plus back-lighting through the
// leaf), tree vertex animation, and screen-door dithering for fading trees (an 8 x 8 Bayer
// ordered-dither matrix, Bayer 1973).
#ifndef UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "Lighting.cginc"
#include "TerrainEngine.cginc"

fixed4 _Color;
fixed3 _TranslucencyColor;
fixed _TranslucencyViewDependency;
half _ShadowStrength;

struct LeafSurfaceOutput {
    fixed3 Albedo;
    fixed3 Normal;
    fixed3 Emission;
    fixed Translucency;
    half Specular;
    fixed Gloss;
    fixed Alpha;
};

// Light passing through the leaf towards the viewer: from behind the leaf (by -n.l) blended
// with looking into the light (by -v.l) by the view dependency.
inline fixed TreeBackLight(half nl, half3 viewDir, half3 lightDir) {
    fixed towardsLight = saturate(dot(viewDir, -lightDir));
    return lerp(saturate(-nl), towardsLight, _TranslucencyViewDependency);
}

inline half4 LightingTreeLeaf(LeafSurfaceOutput s, half3 lightDir, half3 viewDir, half atten) {
    half3 h = SafeNormalize(lightDir + viewDir);
    half nl = dot(s.Normal, lightDir);
    half spec = SafePow(max(0, dot(s.Normal, h)), s.Specular * 128.0) * s.Gloss;
    fixed3 translucency = TreeBackLight(nl, viewDir, lightDir) * s.Translucency * _TranslucencyColor;
    half wrapped = max(0, nl * 0.6 + 0.4);  // wrap lighting: leaves are thin
    fixed4 c;
    c.rgb = (s.Albedo * (translucency * 2 + wrapped)) * _LightColor0.rgb + spec;
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    c.rgb *= lerp(1, atten, _ShadowStrength);
#else
    c.rgb *= atten;
#endif
    c.a = s.Alpha;
    return c;
}

fixed3 ShadeTranslucentMainLight(float4 vertex, float3 normal) {
    float3 viewDir = SafeNormalize(WorldSpaceViewDir(vertex));
    float3 lightDir = SafeNormalize(WorldSpaceLightDir(vertex));
    float nl = dot(normal, lightDir);
    fixed wrapped = max(0, nl * 0.6 + 0.4);
    return _LightColor0.rgb * (wrapped + TreeBackLight(nl, viewDir, lightDir) * _TranslucencyColor);
}

// Ambient and vertex lights on both faces of the leaf.
fixed3 ShadeTranslucentLights(float4 vertex, float3 normal) {
    float3 viewDir = SafeNormalize(WorldSpaceViewDir(vertex));
    float3 mainLightDir = SafeNormalize(WorldSpaceLightDir(vertex));
    float3 front = ShadeSH9(float4(normal, 1.0));
    float3 back = ShadeSH9(float4(-normal, 1.0));
#ifdef VERTEXLIGHT_ON
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    front += Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                               unity_LightColor[0].rgb, unity_LightColor[1].rgb,
                               unity_LightColor[2].rgb, unity_LightColor[3].rgb, unity_4LightAtten0,
                               worldPos, normal);
    back += Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                              unity_LightColor[0].rgb, unity_LightColor[1].rgb,
                              unity_LightColor[2].rgb, unity_LightColor[3].rgb, unity_4LightAtten0,
                              worldPos, -normal);
#endif
    back = lerp(back, back * saturate(dot(viewDir, -mainLightDir)), _TranslucencyViewDependency);
    return 0.5 * (front + back * _TranslucencyColor);
}

void TreeVertBark(inout appdata_full v) {
    v.vertex.xyz *= _TreeInstanceScale.xyz;
    v.vertex = AnimateVertex(v.vertex, v.normal, float4(v.color.xy, v.texcoord1.xy));
    v.vertex = Squash(v.vertex);
    v.color.rgb = _TreeInstanceColor.rgb * _Color.rgb;
    v.normal = SafeNormalize(v.normal);
    v.tangent.xyz = SafeNormalize(v.tangent.xyz);
}
void TreeVertLeaf(inout appdata_full v) {
    ExpandBillboard(UNITY_MATRIX_IT_MV, v.vertex, v.normal, v.tangent);
    TreeVertBark(v);
}

// The 8 x 8 Bayer threshold of a pixel, built by interleaving the bits of x ^ y and y.
float BayerThreshold8x8(int x, int y) {
    int a = x ^ y;
    int v = ((a & 1) << 5) | ((y & 1) << 4) | ((a & 2) << 2) | ((y & 2) << 1) | ((a & 4) >> 1) |
            ((y & 4) >> 2);
    return float(v);
}
// Screen-door transparency: 1 where the pixel is kept at coverage c0.
float ScreenDitherToAlpha(float x, float y, float c0) {
    float limit = (BayerThreshold8x8(int(x) & 7, int(y) & 7) + 11.0) / 64.0;
    return lerp(limit * c0, 1.0, c0);
}
float ComputeAlphaCoverage(float4 screenPos, float fadeAmount) {
    // guard: w = 0 only for a vertex in the camera plane
    float2 pixel = screenPos.xy / (screenPos.w + 0.00001) * _ScreenParams.xy;
    return ScreenDitherToAlpha(pixel.x, pixel.y, fadeAmount);
}

#endif  // UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
