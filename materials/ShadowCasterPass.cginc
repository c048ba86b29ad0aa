// ShadowCasterPass.cginc: the ShadowCaster pass of the shipped lecture shaders, which have no
// alpha cut-out: the object's depth from a light (or in the camera's depth texture), moved by
// Unity's normal and depth biases (UnityCGShadowCaster.cginc). A shader's pass:
//     Pass {
//         Name "ShadowCaster"
//         Tags { "LightMode" = "ShadowCaster" }
//         CGPROGRAM
//         #pragma vertex ShadowCasterVertex
//         #pragma fragment ShadowCasterFragment
//         #pragma multi_compile_shadowcaster
//         #include "ShadowCasterPass.cginc"
//         ENDCG
//     }
#ifndef KILN_SHADOW_CASTER_PASS_INCLUDED
#define KILN_SHADOW_CASTER_PASS_INCLUDED

#include "UnityCG.cginc"

struct ShadowCasterData {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
};

struct ShadowCasterInterpolators {
    V2F_SHADOW_CASTER;
};

ShadowCasterInterpolators ShadowCasterVertex(ShadowCasterData v) {
    ShadowCasterInterpolators o;
    TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
    return o;
}

float4 ShadowCasterFragment(ShadowCasterInterpolators i) : SV_Target {
    SHADOW_CASTER_FRAGMENT(i)
}

#endif  // KILN_SHADOW_CASTER_PASS_INCLUDED
