// The deferred path's light pass (docs/runtime.md, "Deferred rendering"), with the name Unity gives
// its own (Hidden/Internal-DeferredShading). The renderer draws a full-screen triangle per light,
// additively into the light buffer (RT3), with every fragment at a fixed depth (the viewport's
// depth range) tested against the G-buffer's depth, which the pass also samples:
//   LIGHT          a light without a range (and every light of a replacement shader that has only
//                  this pass), drawn at the farthest depth below the clear value: every pixel with
//                  geometry, never the background;
//   LIGHT_MASK     a ranged point or spot light, first: drawn at the near depth of the light's
//                  sphere, it marks in the stencil the pixels not in front of the sphere;
//   LIGHT_BOUNDED  then the light itself, drawn at the sphere's far depth where the stencil is
//                  marked: only pixels within the sphere's depth range are shaded (and unmarked).
// Both draws of a ranged light are scissored to its sphere's rectangle on screen. The light pass
// reads the G-buffer the objects' Deferred passes wrote (UnityGBuffer.cginc), rebuilds the world
// position and shades with the same BRDF, attenuation and shadow as the forward path's additive
// passes (UNITY_LIGHT_ATTENUATION from the world position), so both paths agree up to the
// G-buffer's quantization. A pack loaded before materials.kpack can
// replace it, as Unity allows.
Shader "Hidden/Internal-DeferredShading"
{
    CGINCLUDE
    #include "UnityCG.cginc"
    #include "AutoLight.cginc"
    #include "UnityPBSLighting.cginc"
    #include "UnityGBuffer.cginc"

    sampler2D _CameraGBufferTexture0;
    sampler2D _CameraGBufferTexture1;
    sampler2D _CameraGBufferTexture2;
    UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);

    struct LightVertex {
        float4 position : POSITION;  // a full-screen triangle in clip space
    };

    struct LightInterpolators {
        float4 position : SV_POSITION;
    };

    LightInterpolators LightPassVertex(LightVertex v) {
        LightInterpolators o;
        o.position = float4(v.position.xy, 0.0, 1.0);
        return o;
    }

    float4 LightPassFragment(LightInterpolators i) : SV_Target {
        // SV_Position is the pixel centre in framebuffer coordinates (top-left origin), which is
        // also the G-buffer's texel layout.
        float2 uv = i.position.xy / _ScreenParams.xy;
        float depth = SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv);
        UnityStandardData data = UnityStandardDataFromGbuffer(tex2D(_CameraGBufferTexture0, uv),
                                                              tex2D(_CameraGBufferTexture1, uv),
                                                              tex2D(_CameraGBufferTexture2, uv));
        float3 worldPos = GBuffer_WorldPosition(uv, depth);
        float3 n = data.normalWorld;
        UnityLight light;
        light.dir = SafeNormalize(UnityWorldSpaceLightDir(worldPos));
        UNITY_LIGHT_ATTENUATION(attenuation, 0, worldPos);
        light.color = _LightColor0.rgb * attenuation;
        light.ndotl = DotClamped(n, light.dir);
        UnityIndirect none;
        none.diffuse = 0;
        none.specular = 0;
        float oneMinusReflectivity = 1.0 - SpecularStrength(data.specularColor);
        float3 v = SafeNormalize(UnityWorldSpaceViewDir(worldPos));
        float4 c = UNITY_BRDF_PBS(data.diffuseColor, data.specularColor, oneMinusReflectivity,
                                  data.smoothness, n, v, light, none);
        return float4(c.rgb, 0.0);
    }

    float4 MaskFragment(LightInterpolators i) : SV_Target {
        return 0;
    }
    ENDCG

    SubShader
    {
        Pass
        {
            Name "LIGHT"
            ZWrite Off
            ZTest GEqual  // drawn at the farthest depth: the pixels with geometry
            Cull Off
            Blend One One
            ColorMask RGB

            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment LightPassFragment
            #pragma target 3.0  // GGX, as the Standard shaders' passes
            #pragma multi_compile DIRECTIONAL POINT SPOT
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            // The light's real-time shadow (AutoLight.cginc): screen-space for directional
            // lights, the map for spot lights, the depth cube for point lights.
            #pragma multi_compile_fragment _ SHADOWS_SCREEN SHADOWS_DEPTH SHADOWS_CUBE
            #pragma multi_compile_fragment _ SHADOWS_SOFT
            ENDCG
        }

        Pass
        {
            Name "LIGHT_MASK"
            ZWrite Off
            ZTest LEqual  // drawn at the sphere's near depth: pixels not in front of it
            Cull Off
            ColorMask 0
            Stencil
            {
                Ref 1
                Comp Always
                Pass Replace
            }

            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment MaskFragment
            ENDCG
        }

        Pass
        {
            Name "LIGHT_BOUNDED"
            ZWrite Off
            ZTest GEqual  // drawn at the sphere's far depth: pixels not behind it
            Cull Off
            Blend One One
            ColorMask RGB
            Stencil
            {
                Ref 1
                Comp Equal  // and not in front of it (LIGHT_MASK)
                Pass Zero   // unmarked for the next light
                ZFail Zero
            }

            CGPROGRAM
            #pragma vertex LightPassVertex
            #pragma fragment LightPassFragment
            #pragma target 3.0  // GGX, as the Standard shaders' passes
            #pragma multi_compile DIRECTIONAL POINT SPOT
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            // The light's real-time shadow (AutoLight.cginc): screen-space for directional
            // lights, the map for spot lights, the depth cube for point lights.
            #pragma multi_compile_fragment _ SHADOWS_SCREEN SHADOWS_DEPTH SHADOWS_CUBE
            #pragma multi_compile_fragment _ SHADOWS_SOFT
            ENDCG
        }
    }
}
