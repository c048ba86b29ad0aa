// StandardMetallic: physically based shading in glTF's metallic-roughness parameterization
// (glTF 2.0, Appendix B), for the runtime's glTF scenes. Optional maps are shader_feature
// keywords, so a material that leaves one off gets a variant without its texture reads and
// unused variants can be stripped:
//   _NORMALMAP         tangent-space normal map (needs vertex tangents, xyz + handedness w)
//   _METALLICGLOSSMAP  glTF metallicRoughnessTexture: G = roughness, B = metallic (x factors)
//   _OCCLUSIONMAP      glTF occlusionTexture: R = ambient occlusion (indirect light only)
//   _EMISSION          emissive colour x emission map
//   _ALPHATEST_ON      glTF alphaMode MASK: fragments with base alpha below _Cutoff are discarded
// ForwardBase: the main light, SH ambient and emission; ForwardAdd: one more light per pass;
// Deferred: the G-buffer (UnityGBuffer.cginc) with SH ambient and emission in RT3, lit by the
// deferred path's light pass (materials/internal/DeferredShading.shader) with the same BRDF.
Shader "Kiln/StandardMetallic"
{
    Properties
    {
        [MainColor] _Color ("Base Color", Color) = (1, 1, 1, 1)
        [MainTexture] _MainTex ("Base Color Map", 2D) = "white" {}
        _Metallic ("Metallic", Range(0, 1)) = 1
        _Roughness ("Roughness", Range(0, 1)) = 1
        [Linear] _MetallicGlossMap ("Metallic-Roughness Map", 2D) = "white" {}
        _BumpScale ("Normal Scale", Float) = 1
        [Normal] _BumpMap ("Normal Map", 2D) = "bump" {}
        _OcclusionStrength ("Occlusion Strength", Range(0, 1)) = 1
        [Linear] _OcclusionMap ("Occlusion Map", 2D) = "white" {}
        [HDR] _EmissionColor ("Emission", Color) = (0, 0, 0, 1)
        _EmissionMap ("Emission Map", 2D) = "white" {}
        _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
    }

    CGINCLUDE
    #include "UnityPBSLighting.cginc"
    #include "AutoLight.cginc"
    #include "UnityGBuffer.cginc"

    float4 _Color;
    sampler2D _MainTex;
    float4 _MainTex_ST;
    float _Metallic;
    float _Roughness;
    sampler2D _MetallicGlossMap;
    float _BumpScale;
    sampler2D _BumpMap;
    float _OcclusionStrength;
    sampler2D _OcclusionMap;
    float4 _EmissionColor;
    sampler2D _EmissionMap;
    float _Cutoff;

    struct VertexData {
        float4 position : POSITION;
        float3 normal : NORMAL;
        float2 uv : TEXCOORD0;
    #if defined(_NORMALMAP)
        float4 tangent : TANGENT;
    #endif
    };

    struct Interpolators {
        float4 position : SV_POSITION;
        float2 uv : TEXCOORD0;
        float3 normal : TEXCOORD1;
        float3 worldPos : TEXCOORD2;
    #if defined(_NORMALMAP)
        float4 tangent : TEXCOORD3;  // world-space tangent, w = bitangent sign
    #endif
    };

    Interpolators MetallicVertex(VertexData v) {
        Interpolators i;
        i.position = UnityObjectToClipPos(v.position);
        i.worldPos = mul(unity_ObjectToWorld, float4(v.position.xyz, 1.0)).xyz;
        i.normal = UnityObjectToWorldNormal(v.normal);
        i.uv = TRANSFORM_TEX(v.uv, _MainTex);
    #if defined(_NORMALMAP)
        // guard: a zero handedness would zero the bitangent; glTF requires w = +-1
        i.tangent = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w < 0.0 ? -1.0 : 1.0);
    #endif
        return i;
    }

    float3 SurfaceNormal(Interpolators i) {
        float3 n = SafeNormalize(i.normal);
    #if defined(_NORMALMAP)
        float3 t = SafeNormalize(i.tangent.xyz);
        float3 b = cross(n, t) * i.tangent.w;
        float3 ts = UnpackScaleNormal(tex2D(_BumpMap, i.uv), _BumpScale);
        n = SafeNormalize(ts.x * t + ts.y * b + ts.z * n);
    #endif
        return n;
    }

    struct MetallicSurface {
        float3 diffuse;
        float3 specular;
        float oneMinusReflectivity;
        float smoothness;
        float alpha;
    };

    MetallicSurface ReadSurface(Interpolators i) {
        float4 base = tex2D(_MainTex, i.uv) * _Color;
        float metallic = _Metallic;
        float roughness = _Roughness;
    #if defined(_METALLICGLOSSMAP)
        float4 mr = tex2D(_MetallicGlossMap, i.uv);
        roughness *= mr.g;
        metallic *= mr.b;
    #endif
        MetallicSurface s;
        s.diffuse = DiffuseAndSpecularFromMetallic(base.rgb, metallic, s.specular,
                                                   s.oneMinusReflectivity);
        s.smoothness = 1.0 - saturate(roughness);
        s.alpha = base.a;
    #if defined(_ALPHATEST_ON)
        clip(base.a - _Cutoff);
        s.alpha = 1.0;  // glTF: a MASK material is opaque where it is not cut out
    #endif
        return s;
    }

    float4 ShadeLight(Interpolators i, UnityIndirect indirect) {
        MetallicSurface s = ReadSurface(i);
        float3 n = SurfaceNormal(i);
        UnityLight light;
        light.dir = SafeNormalize(UnityWorldSpaceLightDir(i.worldPos));
        UNITY_LIGHT_ATTENUATION(attenuation, 0, i.worldPos);
        light.color = _LightColor0.rgb * attenuation;
        light.ndotl = DotClamped(n, light.dir);
        float3 v = SafeNormalize(UnityWorldSpaceViewDir(i.worldPos));
        float4 c = UNITY_BRDF_PBS(s.diffuse, s.specular, s.oneMinusReflectivity, s.smoothness, n,
                                  v, light, indirect);
        return float4(c.rgb, s.alpha);
    }

    float4 BaseFragment(Interpolators i) : SV_TARGET {
        float3 n = SurfaceNormal(i);
        float occlusion = 1.0;
    #if defined(_OCCLUSIONMAP)
        occlusion = lerp(1.0, tex2D(_OcclusionMap, i.uv).r, _OcclusionStrength);
    #endif
        UnityIndirect indirect;
        indirect.diffuse = ShadeSH9(float4(n, 1.0)) * occlusion;
        indirect.specular = 0;
        float4 c = ShadeLight(i, indirect);
    #if defined(_EMISSION)
        c.rgb += _EmissionColor.rgb * tex2D(_EmissionMap, i.uv).rgb;
    #endif
        return float4(ClampToHalfRange(c.rgb), c.a);
    }

    struct GBufferOutput {
        float4 gBuffer0 : SV_Target0;
        float4 gBuffer1 : SV_Target1;
        float4 gBuffer2 : SV_Target2;
        float4 gBuffer3 : SV_Target3;
    };

    // The surface into the G-buffer; RT3 gets what BaseFragment adds besides the main light:
    // the SH ambient through the diffuse colour (UNITY_BRDF_PBS's indirect diffuse term) and the
    // emission.
    GBufferOutput DeferredFragment(Interpolators i) {
        MetallicSurface s = ReadSurface(i);
        float3 n = SurfaceNormal(i);
        float occlusion = 1.0;
    #if defined(_OCCLUSIONMAP)
        occlusion = lerp(1.0, tex2D(_OcclusionMap, i.uv).r, _OcclusionStrength);
    #endif
        UnityStandardData data;
        data.diffuseColor = s.diffuse;
        data.occlusion = occlusion;
        data.specularColor = s.specular;
        data.smoothness = s.smoothness;
        data.normalWorld = n;
        GBufferOutput o;
        UnityStandardDataToGbuffer(data, o.gBuffer0, o.gBuffer1, o.gBuffer2);
        float3 emission = s.diffuse * ShadeSH9(float4(n, 1.0)) * occlusion;
    #if defined(_EMISSION)
        emission += _EmissionColor.rgb * tex2D(_EmissionMap, i.uv).rgb;
    #endif
        o.gBuffer3 = GBuffer_EncodeEmission(emission);
        return o;
    }

    float4 AddFragment(Interpolators i) : SV_TARGET {
        UnityIndirect none;
        none.diffuse = 0;
        none.specular = 0;
        return ShadeLight(i, none);
    }
    ENDCG

    SubShader
    {
        Tags { "RenderType" = "Opaque" }

        Pass
        {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex MetallicVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment BaseFragment
            #pragma shader_feature_local _NORMALMAP
            #pragma shader_feature_local_fragment _METALLICGLOSSMAP
            #pragma shader_feature_local_fragment _OCCLUSIONMAP
            #pragma shader_feature_local_fragment _EMISSION
            #pragma shader_feature_local_fragment _ALPHATEST_ON
            ENDCG
        }

        Pass
        {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma vertex MetallicVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment AddFragment
            #pragma multi_compile_fragment DIRECTIONAL POINT SPOT
            #pragma shader_feature_local _NORMALMAP
            #pragma shader_feature_local_fragment _METALLICGLOSSMAP
            #pragma shader_feature_local_fragment _ALPHATEST_ON
            ENDCG
        }

        Pass
        {
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }

            CGPROGRAM
            #pragma vertex MetallicVertex
            #pragma target 3.0  // GGX (UNITY_BRDF_PBS is BRDF3 below shader model 3.0, as in Unity)
            #pragma fragment DeferredFragment
            #pragma multi_compile_fragment _ _GBUFFER_NORMALS_OCT
            #pragma shader_feature_local _NORMALMAP
            #pragma shader_feature_local_fragment _METALLICGLOSSMAP
            #pragma shader_feature_local_fragment _OCCLUSIONMAP
            #pragma shader_feature_local_fragment _EMISSION
            #pragma shader_feature_local_fragment _ALPHATEST_ON
            ENDCG
        }
    }
}
