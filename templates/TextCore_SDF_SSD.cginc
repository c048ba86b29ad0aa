// TextCore_SDF_SSD.cginc: screen-space-derivative signed-distance-field text (Unity's TextCore
// "Distance Field SSD" shader). The glyph atlas stores a distance d in alpha, 0.5 on the edge,
// spread over _GradientScale texels (Green 2007, "Improved alpha-tested magnification for vector
// textures and special effects"). The fragment turns the distance into coverage with a ramp one
// screen pixel wide: the atlas-to-screen scale comes from the UV derivatives.
// Include after UnityCG.cginc and TextCore_Properties.cginc.
#ifndef KILN_TEXTCORE_SDF_SSD_INCLUDED
#define KILN_TEXTCORE_SDF_SSD_INCLUDED

#include "KilnColor.cginc"

struct vertex_t {
    float4 position : POSITION;
    float3 normal : NORMAL;
    float4 color : COLOR;
    float4 texcoord0 : TEXCOORD0;  // xy: atlas UV, w: sign carries bold (<= 0 is bold)
    float2 texcoord1 : TEXCOORD1;
};

struct pixel_t {
    float4 position : SV_POSITION;
    float4 faceColor : COLOR;
    float4 outlineColor : COLOR1;
    float2 texcoord0 : TEXCOORD0;
    float4 param : TEXCOORD1;  // x: edge distance, y: distance-to-pixels scale, z: outline half width
    float2 clipUV : TEXCOORD2;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float4 texcoord2 : TEXCOORD3;  // xy: underlay atlas UV, z: vertex alpha
    float4 underlayColor : COLOR2;
#endif
};

sampler2D _GUIClipTexture;
uniform float4x4 unity_GUIClipTextureMatrix;
float4 _MainTex_TexelSize;

// The IEC 61966-2-1 decode of an sRGB colour (alpha stays linear).
float4 SRGBToLinear(float4 rgba) {
    return float4(SrgbToLinear(rgba.rgb), rgba.a);
}

// Premultiplied colour.
float4 TextCorePremultiply(float4 color) {
    return float4(color.rgb * color.a, color.a);
}

pixel_t VertShader(vertex_t input) {
    float4 objectPosition = input.position;
    objectPosition.xy += float2(_VertexOffsetX, _VertexOffsetY);

    float isBold = input.texcoord0.w <= 0.0 ? 1.0 : 0.0;
    // Dilation in distance units: the style weight (quarter units) plus the face dilate.
    float dilate = (lerp(_WeightNormal, _WeightBold, isBold) * 0.25 + _FaceDilate) * _ScaleRatioA * 0.5;

    float4 vertexColor = input.color;
#if (FORCE_LINEAR && !UNITY_COLORSPACE_GAMMA)
    vertexColor = SRGBToLinear(vertexColor);
#endif
    float opacity = vertexColor.a;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    opacity = 1.0;
#endif

    float4 outline = _OutlineColor;
    outline.a *= opacity;

    pixel_t output;
    output.position = UnityObjectToClipPos(objectPosition);
    output.faceColor = TextCorePremultiply(float4(vertexColor.rgb, opacity) * _FaceColor);
    output.outlineColor = TextCorePremultiply(outline);
    output.texcoord0 = input.texcoord0.xy;
    float pixelsPerDistance = 1.3333 * _GradientScale * (_Sharpness + 1.0) / _MainTex_TexelSize.z;
    output.param = float4(0.5 - dilate, pixelsPerDistance, _OutlineWidth * _ScaleRatioA * 0.5, 0.0);
    float3 viewPosition = UnityObjectToViewPos(input.position.xyz);
    output.clipUV = mul(unity_GUIClipTextureMatrix, float4(viewPosition.xy, 0.0, 1.0)).xy;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float2 underlayShift = -float2(_UnderlayOffsetX, _UnderlayOffsetY) * _ScaleRatioC *
                           _GradientScale / _MainTex_TexelSize.zw;
    output.texcoord2 = float4(input.texcoord0.xy + underlayShift, input.color.a, 0.0);
    output.underlayColor = TextCorePremultiply(_UnderlayColor);
#endif
    return output;
}

// Coverage of a distance ramp centred on `edge`, `scale` pixels per distance unit.
float TextCoreCoverage(float distance, float edge, float scale) {
    return saturate((distance - edge) * scale + 0.5);
}

float4 PixShader(pixel_t input) : SV_Target {
    float2 uv = input.texcoord0.xy;
    float distance = tex2D(_MainTex, uv).a;
    // Screen pixels per atlas unit: the inverse square root of the UV Jacobian's determinant.
    float jacobian = abs(ddx(uv.x) * ddy(uv.y) - ddy(uv.x) * ddx(uv.y));
    float scale = rsqrt(max(jacobian, 1e-20)) * input.param.y;
#if (UNDERLAY_ON || UNDERLAY_INNER)
    float layerScale = scale / (1.0 + _UnderlaySoftness * _ScaleRatioC * scale);
    float layerBias = input.param.x * layerScale - 0.5 - _UnderlayDilate * _ScaleRatioC * 0.5 * layerScale;
#endif
    scale /= 1.0 + _OutlineSoftness * _ScaleRatioA * scale;

    float edge = input.param.x;
    float4 color = input.faceColor * TextCoreCoverage(distance, edge, scale);
#ifdef OUTLINE_ON
    float halfWidth = input.param.z;
    float4 outlined = lerp(input.faceColor, input.outlineColor, sqrt(min(1.0, halfWidth * scale * 2.0)));
    color = lerp(outlined, input.faceColor, TextCoreCoverage(distance, edge + halfWidth, scale));
    color *= TextCoreCoverage(distance, edge - halfWidth, scale);
#endif
#if UNDERLAY_ON
    float under = tex2D(_MainTex, input.texcoord2.xy).a * layerScale;
    color += input.underlayColor * saturate(under - layerBias) * (1.0 - color.a);
#endif
#if UNDERLAY_INNER
    float inside = saturate(distance * scale - (edge * scale - 0.5) - input.param.z);
    float inner = tex2D(_MainTex, input.texcoord2.xy).a * layerScale;
    color += input.underlayColor * (1.0 - saturate(inner - layerBias)) * inside * (1.0 - color.a);
#endif
#if (UNDERLAY_ON || UNDERLAY_INNER)
    color *= input.texcoord2.z;
#endif
    return color * tex2D(_GUIClipTexture, input.clipUV).a;
}

#endif  // KILN_TEXTCORE_SDF_SSD_INCLUDED
