// The screen-space shadow collector (docs/runtime.md, "Shadows"), with the name Unity gives its own
// (Hidden/Internal-ScreenSpaceShadows). For a shadowed directional light the renderer draws a
// full-screen triangle into a single-channel screen target: each pixel rebuilds its world position
// from the camera's depth (drawn by the objects' ShadowCaster passes), projects it into the light's
// shadow map (unity_WorldToShadow[0]) and compares; the lit fraction is written, 1 where the
// camera sees no geometry. The forward passes with SHADOWS_SCREEN then read it at their pixel
// (AutoLight.cginc). SHADOWS_SOFT filters over 5 x 5 bilinear comparison taps (2x2 each), a
// penumbra about 5 shadow-map texels wide, as Unity's PCF 5x5; without it one tap filters 2x2
// texels (hard shadows with smooth texel edges).
Shader "Hidden/Internal-ScreenSpaceShadows"
{
    CGINCLUDE
    #include "UnityCG.cginc"
    #include "UnityGBuffer.cginc"

    UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
    UNITY_DECLARE_SHADOWMAP(_ShadowMapTexture);
    float4 _ShadowMapTexture_TexelSize;

    struct CollectVertex {
        float4 position : POSITION;  // a full-screen triangle in clip space
    };

    struct CollectInterpolators {
        float4 position : SV_POSITION;
    };

    CollectInterpolators CollectShadowsVertex(CollectVertex v) {
        CollectInterpolators o;
        o.position = float4(v.position.xy, 0.0, 1.0);
        return o;
    }

    // The lit fraction at a shadow-map coordinate (u, v, depth): one bilinear comparison tap, or
    // with SHADOWS_SOFT the mean of 5 x 5 taps a texel apart.
    half CollectedShadow(float3 coord) {
#if defined(SHADOWS_SOFT)
        half sum = 0.0;
        for (int y = -2; y <= 2; ++y) {
            for (int x = -2; x <= 2; ++x) {
                float2 offset = float2(x, y) * _ShadowMapTexture_TexelSize.xy;
                sum += UNITY_SAMPLE_SHADOW(_ShadowMapTexture, float3(coord.xy + offset, coord.z));
            }
        }
        return sum / 25.0;
#else
        return UNITY_SAMPLE_SHADOW(_ShadowMapTexture, coord);
#endif
    }

    float4 CollectShadowsFragment(CollectInterpolators i) : SV_Target {
        // SV_Position is the pixel centre in framebuffer coordinates (top-left origin), which is
        // also the depth texture's texel layout.
        float2 uv = i.position.xy / _ScreenParams.xy;
        float depth = SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv);
        if (depth >= 1.0)
            return 1.0;  // no geometry: nothing to shadow
        float3 worldPos = GBuffer_WorldPosition(uv, depth);
        // An orthographic light: w = 1.
        float3 coord = mul(unity_WorldToShadow[0], float4(worldPos, 1.0)).xyz;
        half shadow = CollectedShadow(coord);
        return lerp(_LightShadowData.r, 1.0, shadow);
    }
    ENDCG

    SubShader
    {
        Pass
        {
            ZWrite Off
            ZTest Always
            Cull Off

            CGPROGRAM
            #pragma vertex CollectShadowsVertex
            #pragma fragment CollectShadowsFragment
            #pragma multi_compile_fragment _ SHADOWS_SOFT
            ENDCG
        }
    }
}
