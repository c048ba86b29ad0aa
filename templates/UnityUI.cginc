// UnityUI.cginc: helpers of Unity's UI shaders: rectangle clipping, the UI texture with a
// separate alpha texture, and UI colours (authored in gamma space) to linear.
#ifndef UNITY_UI_INCLUDED
#define UNITY_UI_INCLUDED

#include "KilnColor.cginc"

// 1 inside the clip rectangle (xy: min corner, zw: max corner), 0 outside.
inline float UnityGet2DClipping(in float2 position, in float4 clipRect) {
    float2 inside = step(clipRect.xy, position.xy) * step(position.xy, clipRect.zw);
    return inside.x * inside.y;
}

inline fixed4 UnityGetUIDiffuseColor(in float2 position, in sampler2D mainTexture,
                                     in sampler2D alphaTexture, fixed4 textureSampleAdd) {
    return fixed4(tex2D(mainTexture, position).rgb + textureSampleAdd.rgb,
                  tex2D(alphaTexture, position).r + textureSampleAdd.a);
}

// sRGB-encoded UI colour to linear (IEC 61966-2-1; Unity uses a polynomial fit of it).
half3 UIGammaToLinear(half3 value) {
    return SrgbToLinear(value);
}

#endif  // UNITY_UI_INCLUDED
