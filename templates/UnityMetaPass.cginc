// UnityMetaPass.cginc: the Meta pass helpers with Unity's names. Unity's lightmapper renders
// Meta passes in UV space to read albedo and emission; the editor's visualization modes
// (EDITOR_VISUALIZATION) show textures, light masks and PBR-validation colours. Kiln's runtime
// draws no Meta passes; these compile them with the same outputs.
#ifndef UNITY_META_PASS_INCLUDED
#define UNITY_META_PASS_INCLUDED

#include "UnityCG.cginc"

CBUFFER_START(UnityMetaPass)
    bool4 unity_MetaVertexControl;    // x: place the vertex at UV1 (lightmap), y: at UV2
    bool4 unity_MetaFragmentControl;  // x: output albedo, y: output emission
    int unity_VisualizationMode;
CBUFFER_END

struct UnityMetaInput {
    half3 Albedo;
    half3 Emission;
    half3 SpecularColor;
#ifdef EDITOR_VISUALIZATION
    float2 VizUV;
    float4 LightCoord;
#endif
};

#define EDITORVIZ_PBR_VALIDATION_ALBEDO 0
#define EDITORVIZ_PBR_VALIDATION_METALSPECULAR 1
#define EDITORVIZ_TEXTURE 2
#define EDITORVIZ_SHOWLIGHTMASK 3
#define PBR_VALIDATION_ALBEDO EDITORVIZ_PBR_VALIDATION_ALBEDO
#define PBR_VALIDATION_METALSPECULAR EDITORVIZ_PBR_VALIDATION_METALSPECULAR

// The editor's validation and visualization settings.
int _CheckPureMetal;
int _CheckAlbedo;
half4 _AlbedoCompareColor;
half _AlbedoMinLuminance;
half _AlbedoMaxLuminance;
half _AlbedoHueTolerance;
half _AlbedoSaturationTolerance;
sampler2D unity_EditorViz_Texture;
half4 unity_EditorViz_Texture_ST;
int unity_EditorViz_UVIndex;
half4 unity_EditorViz_Decode_HDR;
bool unity_EditorViz_ConvertToLinearSpace;
half4 unity_EditorViz_ColorMul;
half4 unity_EditorViz_ColorAdd;
half unity_EditorViz_Exposure;
sampler2D unity_EditorViz_LightTexture;
sampler2D unity_EditorViz_LightTextureB;
#define unity_EditorViz_ChannelSelect unity_EditorViz_ColorMul
#define unity_EditorViz_Color unity_EditorViz_ColorAdd
#define unity_EditorViz_LightType unity_EditorViz_UVIndex
float4x4 unity_EditorViz_WorldToLight;
half4 unity_MaterialValidateLowColor;
half4 unity_MaterialValidateHighColor;
half4 unity_MaterialValidatePureMetalColor;
float unity_OneOverOutputBoost;
float unity_MaxOutputValue;
float unity_UseLinearSpace;

// RGB -> (hue, saturation, value), hue in [0, 1) (Smith 1978).
half3 UnityMeta_RGBToHSV(half3 c) {
    half maxC = max(c.r, max(c.g, c.b));
    half minC = min(c.r, min(c.g, c.b));
    half delta = maxC - minC;
    half h = 0;
    if (delta > 1e-5) {
        if (maxC == c.r)
            h = (c.g - c.b) / delta;
        else if (maxC == c.g)
            h = 2.0 + (c.b - c.r) / delta;
        else
            h = 4.0 + (c.r - c.g) / delta;
        h = frac(h / 6.0 + 1.0);
    }
    half s = maxC > 1e-5 ? delta / maxC : 0;
    return half3(h, s, maxC);
}
half3 UnityMeta_RGBToHSVHelper(float offset, half dominantColor, half colorone, half colortwo) {
    half delta = dominantColor - min(colorone, colortwo);
    half h = delta > 1e-5 ? frac((offset + (colorone - colortwo) / delta) / 6.0 + 1.0) : 0;
    return half3(h, dominantColor > 1e-5 ? delta / dominantColor : 0, dominantColor);
}

// Albedo validation: too dark, too bright, or outside the compare colour's hue and saturation.
half4 UnityMeta_pbrAlbedo(UnityMetaInput IN) {
    half luminance = Luminance(IN.Albedo);
    if (_CheckAlbedo == 0) {
        if (luminance < _AlbedoMinLuminance)
            return unity_MaterialValidateLowColor;
        if (luminance > _AlbedoMaxLuminance)
            return unity_MaterialValidateHighColor;
        return half4(IN.Albedo, 0);
    }
    half3 hsv = UnityMeta_RGBToHSV(IN.Albedo);
    half3 compare = UnityMeta_RGBToHSV(_AlbedoCompareColor.rgb);
    half hueDistance = min(abs(hsv.x - compare.x), 1.0 - abs(hsv.x - compare.x));
    if (hueDistance > _AlbedoHueTolerance || abs(hsv.y - compare.y) > _AlbedoSaturationTolerance)
        return unity_MaterialValidateHighColor;
    return half4(IN.Albedo, 0);
}
// Metal/specular validation: specular colours a dielectric cannot have (below 4%, or metals with
// a dark albedo when pure metals are checked).
half4 UnityMeta_pbrMetalspec(UnityMetaInput IN) {
    half specularLuminance = Luminance(IN.SpecularColor);
    if (specularLuminance < 0.02)
        return unity_MaterialValidateLowColor;
    if (_CheckPureMetal && specularLuminance > 0.45 && Luminance(IN.Albedo) > 0.01)
        return unity_MaterialValidatePureMetalColor;
    return half4(IN.SpecularColor, 0);
}

float2 UnityMetaVizUV(int uvIndex, float2 uv0, float2 uv1, float2 uv2, float4 st) {
    float2 uv = uvIndex == 0 ? uv0 : (uvIndex == 1 ? uv1 : uv2);
    return uv * st.xy + st.zw;
}

// The vertex at its lightmap UV (the lightmapper's raster position), or its ordinary position.
float4 UnityMetaVertexPosition(float4 vertex, float2 uv1, float2 uv2, float4 lightmapST,
                               float4 dynlightmapST) {
#if !defined(EDITOR_VISUALIZATION)
    if (unity_MetaVertexControl.x) {
        vertex.xy = uv1 * lightmapST.xy + lightmapST.zw;
        vertex.z = vertex.z > 0 ? 1.0e-4f : 0.0f;  // keep z used
    }
    if (unity_MetaVertexControl.y) {
        vertex.xy = uv2 * dynlightmapST.xy + dynlightmapST.zw;
        vertex.z = vertex.z > 0 ? 1.0e-4f : 0.0f;
    }
    return mul(UNITY_MATRIX_VP, float4(vertex.xyz, 1.0));
#else
    return UnityObjectToClipPos(vertex);
#endif
}

half4 UnityMetaFragment(UnityMetaInput IN) {
    half4 res = 0;
#if !defined(EDITOR_VISUALIZATION)
    if (unity_MetaFragmentControl.x) {
        // albedo, with the lightmapper's boost (an exponent below 1) and upper bound
        res = half4(clamp(pow(max(IN.Albedo, 0.0), saturate(unity_OneOverOutputBoost)), 0,
                          unity_MaxOutputValue),
                    1);
    }
    if (unity_MetaFragmentControl.y) {
        res = half4(unity_UseLinearSpace ? IN.Emission : GammaToLinearSpace(IN.Emission), 1.0);
    }
#else
    if (unity_VisualizationMode == EDITORVIZ_PBR_VALIDATION_ALBEDO) {
        res = UnityMeta_pbrAlbedo(IN);
    } else if (unity_VisualizationMode == EDITORVIZ_PBR_VALIDATION_METALSPECULAR) {
        res = UnityMeta_pbrMetalspec(IN);
    } else if (unity_VisualizationMode == EDITORVIZ_TEXTURE) {
        res = tex2D(unity_EditorViz_Texture, IN.VizUV);
        if (unity_EditorViz_Decode_HDR.x > 0)
            res = half4(DecodeHDR(res, unity_EditorViz_Decode_HDR), 1);
        if (unity_EditorViz_ConvertToLinearSpace)
            res.rgb = LinearToGammaSpace(res.rgb);
        res = (res * unity_EditorViz_ColorMul + unity_EditorViz_ColorAdd) *
              exp2(unity_EditorViz_Exposure);
    } else if (unity_VisualizationMode == EDITORVIZ_SHOWLIGHTMASK) {
        float mask = dot(unity_EditorViz_ChannelSelect, tex2D(unity_EditorViz_Texture, IN.VizUV));
        if (mask == 0)
            discard;
        res = float4(unity_EditorViz_Color.xyz * mask, unity_EditorViz_Color.w);
    }
#endif
    return res;
}

#endif  // UNITY_META_PASS_INCLUDED
