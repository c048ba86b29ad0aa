// StandardMetallic: physically based shading in glTF's metallic-roughness parameterization
// (glTF 2.0, Appendix B), for the runtime's glTF scenes. Optional maps are shader_feature
// keywords, so a material that leaves one off gets a variant without its texture reads and
// unused variants can be stripped:
//   _NORMALMAP         tangent-space normal map (needs vertex tangents, xyz + handedness w)
//   _METALLICGLOSSMAP  glTF metallicRoughnessTexture: G = roughness, B = metallic (x factors)
//   _OCCLUSIONMAP      glTF occlusionTexture: R = ambient occlusion (indirect light only)
//   _EMISSION          emissive colour x emission map
//   _ALPHATEST_ON      glTF alphaMode MASK: fragments with base alpha below _Cutoff are discarded
// As glTF has it, each map has its own tiling and offset (<map>_ST), UV set and rotation
// (<map>_UV; GltfTexture.cginc), the base colour is multiplied by the vertex colour (white where
// the mesh has none), and a back face (drawn with Cull Off) is lit with its normal reversed.
// ForwardBase: the main light, SH ambient, the reflection probe (unity_SpecCube0: the ambient
// environment prefiltered per roughness mip) and emission; ForwardAdd: one more light per pass;
// Deferred: the G-buffer (UnityGBuffer.cginc) with the ambient (SH and probe) and emission in
// RT3, lit by the deferred path's light pass (materials/internal/DeferredShading.shader) with
// the same BRDF.
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
        // Each map's UV set (x: 0 or 1) and rotation (y, radians): glTF's texCoord and
        // KHR_texture_transform (its scale and offset are the map's tiling and offset).
        [HideInInspector] _MainTex_UV ("Base Color Map UV", Vector) = (0, 0, 0, 0)
        [HideInInspector] _MetallicGlossMap_UV ("Metallic-Roughness Map UV", Vector) = (0, 0, 0, 0)
        [HideInInspector] _BumpMap_UV ("Normal Map UV", Vector) = (0, 0, 0, 0)
        [HideInInspector] _OcclusionMap_UV ("Occlusion Map UV", Vector) = (0, 0, 0, 0)
        [HideInInspector] _EmissionMap_UV ("Emission Map UV", Vector) = (0, 0, 0, 0)
    }

    CGINCLUDE
    #include "UnityPBSLighting.cginc"
    #include "AutoLight.cginc"
    #include "UnityGBuffer.cginc"
    #include "GltfTexture.cginc"

    float4 _Color;
    sampler2D _MainTex;
    float4 _MainTex_ST, _MainTex_UV;
    float _Metallic;
    float _Roughness;
    sampler2D _MetallicGlossMap;
    float4 _MetallicGlossMap_ST, _MetallicGlossMap_UV;
    float _BumpScale;
    sampler2D _BumpMap;
    float4 _BumpMap_ST, _BumpMap_UV;
    float _OcclusionStrength;
    sampler2D _OcclusionMap;
    float4 _OcclusionMap_ST, _OcclusionMap_UV;
    float4 _EmissionColor;
    sampler2D _EmissionMap;
    float4 _EmissionMap_ST, _EmissionMap_UV;
    float _Cutoff;

    struct VertexData {
        float4 position : POSITION;
        float3 normal : NORMAL;
        float2 uv : TEXCOORD0;
        float2 uv1 : TEXCOORD1;
        float4 color : COLOR;
    #if defined(_NORMALMAP)
        float4 tangent : TANGENT;
    #endif
    };

    struct Interpolators {
        float4 position : SV_POSITION;
        float4 uv : TEXCOORD0;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw, untransformed
        float3 normal : TEXCOORD1;
        float3 worldPos : TEXCOORD2;
        float4 color : TEXCOORD3;  // the vertex colour, linear
    #if defined(_NORMALMAP)
        float4 tangent : TEXCOORD4;  // world-space tangent, w = bitangent sign
    #endif
    };

    Interpolators MetallicVertex(VertexData v) {
        Interpolators i;
        i.position = UnityObjectToClipPos(v.position);
        i.worldPos = mul(unity_ObjectToWorld, float4(v.position.xyz, 1.0)).xyz;
        i.normal = UnityObjectToWorldNormal(v.normal);
        i.uv = float4(v.uv, v.uv1);
        i.color = v.color;
    #if defined(_NORMALMAP)
        // guard: a zero handedness would zero the bitangent; glTF requires w = +-1. A mirroring
        // transform reverses the bitangent too (unity_WorldTransformParams.w = -1).
        float sign = (v.tangent.w < 0.0 ? -1.0 : 1.0) * unity_WorldTransformParams.w;
        i.tangent = float4(UnityObjectToWorldDir(v.tangent.xyz), sign);
    #endif
        return i;
    }

    // The shading normal; a back face (front = false, drawn only with Cull Off) has its whole
    // frame reversed, so that it is lit as seen from its own side (glTF 2.0, 3.9.5).
    float3 SurfaceNormal(Interpolators i, bool front) {
        float side = front ? 1.0 : -1.0;
        float3 n = SafeNormalize(i.normal) * side;
    #if defined(_NORMALMAP)
        float3 t = SafeNormalize(i.tangent.xyz) * side;
        float3 b = cross(n, t) * i.tangent.w;  // the reversed n and t give back b; reverse it too
        b *= side;
        float3 ts = UnpackScaleNormal(tex2D(_BumpMap, GLTF_MAP_UV(i.uv, _BumpMap)), _BumpScale);
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
        float4 base = tex2D(_MainTex, GLTF_MAP_UV(i.uv, _MainTex)) * _Color * i.color;
        float metallic = _Metallic;
        float roughness = _Roughness;
    #if defined(_METALLICGLOSSMAP)
        float4 mr = tex2D(_MetallicGlossMap, GLTF_MAP_UV(i.uv, _MetallicGlossMap));
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

    float4 ShadeLight(Interpolators i, bool front, UnityIndirect indirect) {
        MetallicSurface s = ReadSurface(i);
        float3 n = SurfaceNormal(i, front);
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

    float Occlusion(Interpolators i) {
        float occlusion = 1.0;
    #if defined(_OCCLUSIONMAP)
        float ao = tex2D(_OcclusionMap, GLTF_MAP_UV(i.uv, _OcclusionMap)).r;
        occlusion = lerp(1.0, ao, _OcclusionStrength);
    #endif
        return occlusion;
    }

    float3 Emission(Interpolators i) {
    #if defined(_EMISSION)
        return _EmissionColor.rgb * tex2D(_EmissionMap, GLTF_MAP_UV(i.uv, _EmissionMap)).rgb;
    #else
        return 0;
    #endif
    }

    // The ambient light at the fragment: SH irradiance and the reflection probe's prefiltered
    // radiance along the reflected view direction, at the mip of the surface's roughness
    // (Unity_GlossyEnvironment), both times the occlusion.
    UnityIndirect Ambient(Interpolators i, float3 n, float smoothness) {
        float occlusion = Occlusion(i);
        float3 v = SafeNormalize(UnityWorldSpaceViewDir(i.worldPos));
        Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(smoothness, v, n, 0);
        UnityIndirect indirect;
        indirect.diffuse = ShadeSH9(float4(n, 1.0)) * occlusion;
        indirect.specular = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0),
                                                    unity_SpecCube0_HDR, g) * occlusion;
        return indirect;
    }

    float4 BaseFragment(Interpolators i, bool front : SV_IsFrontFace) : SV_TARGET {
        float3 n = SurfaceNormal(i, front);
        UnityIndirect indirect = Ambient(i, n, ReadSurface(i).smoothness);
        float4 c = ShadeLight(i, front, indirect);
        c.rgb += Emission(i);
        return float4(ClampToHalfRange(c.rgb), c.a);
    }

    struct GBufferOutput {
        float4 gBuffer0 : SV_Target0;
        float4 gBuffer1 : SV_Target1;
        float4 gBuffer2 : SV_Target2;
        float4 gBuffer3 : SV_Target3;
    };

    // The surface into the G-buffer; RT3 gets what BaseFragment adds besides the main light:
    // UNITY_BRDF_PBS's ambient terms (SH through the diffuse colour, the probe through the
    // Fresnel and surface reduction) with no direct light, and the emission.
    GBufferOutput DeferredFragment(Interpolators i, bool front : SV_IsFrontFace) {
        MetallicSurface s = ReadSurface(i);
        float3 n = SurfaceNormal(i, front);
        float occlusion = Occlusion(i);
        UnityLight none;
        none.color = 0;
        none.dir = n;
        none.ndotl = 0;
        float3 v = SafeNormalize(UnityWorldSpaceViewDir(i.worldPos));
        float3 ambient = UNITY_BRDF_PBS(s.diffuse, s.specular, s.oneMinusReflectivity,
                                       s.smoothness, n, v, none, Ambient(i, n, s.smoothness)).rgb;
        UnityStandardData data;
        data.diffuseColor = s.diffuse;
        data.occlusion = occlusion;
        data.specularColor = s.specular;
        data.smoothness = s.smoothness;
        data.normalWorld = n;
        GBufferOutput o;
        UnityStandardDataToGbuffer(data, o.gBuffer0, o.gBuffer1, o.gBuffer2);
        float3 emission = ambient + Emission(i);
        o.gBuffer3 = GBuffer_EncodeEmission(emission);
        return o;
    }

    float4 AddFragment(Interpolators i, bool front : SV_IsFrontFace) : SV_TARGET {
        UnityIndirect none;
        none.diffuse = 0;
        none.specular = 0;
        return ShadeLight(i, front, none);
    }

    // The ShadowCaster pass: depth from the light (or the camera's depth texture), moved by
    // Unity's normal and depth biases (UnityCGShadowCaster.cginc); MASK materials cut out what
    // their base colour's alpha cuts out.
    struct ShadowVertexData {
        float4 vertex : POSITION;
        float3 normal : NORMAL;
        float2 uv : TEXCOORD0;
        float2 uv1 : TEXCOORD1;
        float4 color : COLOR;
    };

    struct ShadowInterpolators {
        V2F_SHADOW_CASTER;
        float4 uv : TEXCOORD1;
        float alpha : TEXCOORD2;  // the vertex colour's
    };

    ShadowInterpolators ShadowVertex(ShadowVertexData v) {
        ShadowInterpolators o;
        TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
        o.uv = float4(v.uv, v.uv1);
        o.alpha = v.color.a;
        return o;
    }

    float4 ShadowFragment(ShadowInterpolators i) : SV_TARGET {
    #if defined(_ALPHATEST_ON)
        float alpha = _Color.a * tex2D(_MainTex, GLTF_MAP_UV(i.uv, _MainTex)).a * i.alpha;
        clip(alpha - _Cutoff);
    #endif
        SHADOW_CASTER_FRAGMENT(i)
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
            #pragma multi_compile_fragment _ SHADOWS_SCREEN
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
            // Unity's light and shadow combinations (SHADOWS_SCREEN for directional lights,
            // SHADOWS_DEPTH for spot, SHADOWS_CUBE for point, SHADOWS_SOFT with the last two),
            // without cookies and baked shadows, which Kiln does not render.
            #pragma multi_compile_fwdadd_fullshadows
            #pragma skip_variants POINT_COOKIE DIRECTIONAL_COOKIE
            #pragma skip_variants SHADOWS_SHADOWMASK LIGHTMAP_SHADOW_MIXING
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

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual

            CGPROGRAM
            #pragma vertex ShadowVertex
            #pragma fragment ShadowFragment
            #pragma multi_compile_shadowcaster
            #pragma shader_feature_local_fragment _ALPHATEST_ON
            ENDCG
        }
    }
}
