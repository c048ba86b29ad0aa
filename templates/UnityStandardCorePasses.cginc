// UnityStandardCorePasses.cginc (part of UnityStandardCore.cginc): the vertex and fragment
// programs of the Standard shader's ForwardBase, ForwardAdd and Deferred passes.
#ifndef UNITY_STANDARD_CORE_PASSES_INCLUDED
#define UNITY_STANDARD_CORE_PASSES_INCLUDED

// ---- ForwardBase: the main directional light, emission, ambient and vertex lights ----
struct VertexOutputForwardBase {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;  // xyz: camera to vertex; w: fog
    // rows of the tangent frame; w: the parallax view direction or the world position
    float4 tangentToWorldAndPackedData[3] : TEXCOORD2;
    half4 ambientOrLightmapUV : TEXCOORD5;  // SH and vertex lights, or lightmap UVs
    UNITY_LIGHTING_COORDS(6, 7)
#if UNITY_REQUIRE_FRAG_WORLDPOS && !UNITY_PACK_WORLDPOS_WITH_TANGENT
    float3 posWorld : TEXCOORD8;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardBase vertForwardBase(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardBase o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardBase, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec.xyz = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    WriteTangentFrame(v, normalWorld, o.tangentToWorldAndPackedData);
#if UNITY_REQUIRE_FRAG_WORLDPOS
#if UNITY_PACK_WORLDPOS_WITH_TANGENT
    o.tangentToWorldAndPackedData[0].w = posWorld.x;
    o.tangentToWorldAndPackedData[1].w = posWorld.y;
    o.tangentToWorldAndPackedData[2].w = posWorld.z;
#else
    o.posWorld = posWorld.xyz;
#endif
#endif
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    o.ambientOrLightmapUV = VertexGIForward(v, posWorld.xyz, normalWorld);
#ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    half3 viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
    o.tangentToWorldAndPackedData[0].w = viewDirForParallax.x;
    o.tangentToWorldAndPackedData[1].w = viewDirForParallax.y;
    o.tangentToWorldAndPackedData[2].w = viewDirForParallax.z;
#endif
    UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, o.pos);
    return o;
}

half4 fragForwardBaseInternal(VertexOutputForwardBase i) {
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
    UnityLight mainLight = MainLight();
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    half occlusion = Occlusion(i.tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, atten, mainLight);
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness,
                             s.normalWorld, -s.eyeVec, gi.light, gi.indirect);
    c.rgb += Emission(i.tex.xy);
    UNITY_EXTRACT_FOG_FROM_EYE_VEC(i);
    UNITY_APPLY_FOG(_unity_fogCoord, c.rgb);
    return OutputForward(c, s.alpha);
}
half4 fragForwardBase(VertexOutputForwardBase i) : SV_Target {
    return fragForwardBaseInternal(i);
}

// ---- ForwardAdd: one more pixel light, added ----
struct VertexOutputForwardAdd {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;  // xyz: camera to vertex; w: fog
    // rows of the tangent frame; w: the direction to the light
    float4 tangentToWorldAndLightDir[3] : TEXCOORD2;
    float3 posWorld : TEXCOORD5;
    UNITY_LIGHTING_COORDS(6, 7)
#if defined(_PARALLAXMAP)
    half3 viewDirForParallax : TEXCOORD8;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardAdd vertForwardAdd(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardAdd o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardAdd, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec.xyz = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    o.posWorld = posWorld.xyz;
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    WriteTangentFrame(v, normalWorld, o.tangentToWorldAndLightDir);
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    float3 lightDir = _WorldSpaceLightPos0.xyz - posWorld.xyz * _WorldSpaceLightPos0.w;
#ifndef USING_DIRECTIONAL_LIGHT
    lightDir = NormalizePerVertexNormal(lightDir);
#endif
    o.tangentToWorldAndLightDir[0].w = lightDir.x;
    o.tangentToWorldAndLightDir[1].w = lightDir.y;
    o.tangentToWorldAndLightDir[2].w = lightDir.z;
#ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    o.viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
#endif
    UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, o.pos);
    return o;
}

half4 fragForwardAddInternal(VertexOutputForwardAdd i) {
    FRAGMENT_SETUP_FWDADD(s)
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    UnityLight light = AdditiveLight(IN_LIGHTDIR_FWDADD(i), atten);
    UnityIndirect noIndirect = ZeroIndirect();
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness,
                             s.normalWorld, -s.eyeVec, light, noIndirect);
    UNITY_EXTRACT_FOG_FROM_EYE_VEC(i);
    UNITY_APPLY_FOG_COLOR(_unity_fogCoord, c.rgb, half4(0, 0, 0, 0));  // additive: towards black
    return OutputForward(c, s.alpha);
}
half4 fragForwardAdd(VertexOutputForwardAdd i) : SV_Target {
    return fragForwardAddInternal(i);
}

// ---- Deferred: the G-buffer (RT0 diffuse + occlusion, RT1 specular + smoothness, RT2 normal,
// RT3 emission + indirect light) ----
struct VertexOutputDeferred {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 eyeVec : TEXCOORD1;
    float4 tangentToWorldAndPackedData[3] : TEXCOORD2;
    half4 ambientOrLightmapUV : TEXCOORD5;
#if UNITY_REQUIRE_FRAG_WORLDPOS && !UNITY_PACK_WORLDPOS_WITH_TANGENT
    float3 posWorld : TEXCOORD6;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputDeferred vertDeferred(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputDeferred o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputDeferred, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    WriteTangentFrame(v, normalWorld, o.tangentToWorldAndPackedData);
#if UNITY_REQUIRE_FRAG_WORLDPOS
#if UNITY_PACK_WORLDPOS_WITH_TANGENT
    o.tangentToWorldAndPackedData[0].w = posWorld.x;
    o.tangentToWorldAndPackedData[1].w = posWorld.y;
    o.tangentToWorldAndPackedData[2].w = posWorld.z;
#else
    o.posWorld = posWorld.xyz;
#endif
#endif
    o.ambientOrLightmapUV = 0;
#ifdef LIGHTMAP_ON
    o.ambientOrLightmapUV.xy = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
#elif UNITY_SHOULD_SAMPLE_SH
    o.ambientOrLightmapUV.rgb = ShadeSHPerVertex(normalWorld, o.ambientOrLightmapUV.rgb);
#endif
#ifdef DYNAMICLIGHTMAP_ON
    o.ambientOrLightmapUV.zw = v.uv2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
#endif
#ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    half3 viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
    o.tangentToWorldAndPackedData[0].w = viewDirForParallax.x;
    o.tangentToWorldAndPackedData[1].w = viewDirForParallax.y;
    o.tangentToWorldAndPackedData[2].w = viewDirForParallax.z;
#endif
    return o;
}

void fragDeferred(VertexOutputDeferred i, out half4 outGBuffer0 : SV_Target0,
                  out half4 outGBuffer1 : SV_Target1, out half4 outGBuffer2 : SV_Target2,
                  out half4 outEmission : SV_Target3
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
                  , out half4 outShadowMask : SV_Target4
#endif
) {
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);
    // The G-buffer pass has no light: indirect light only (reflections come from the
    // reflection-probe pass when UNITY_ENABLE_REFLECTION_BUFFERS).
    UnityLight dummyLight = DummyLight();
    half atten = 1;
    half occlusion = Occlusion(i.tex.xy);
#if UNITY_ENABLE_REFLECTION_BUFFERS
    bool sampleReflectionsInDeferred = false;
#else
    bool sampleReflectionsInDeferred = true;
#endif
    UnityGI gi =
        FragmentGI(s, occlusion, i.ambientOrLightmapUV, atten, dummyLight, sampleReflectionsInDeferred);
    half3 emissiveColor = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity,
                                         s.smoothness, s.normalWorld, -s.eyeVec, gi.light,
                                         gi.indirect).rgb;
#ifdef _EMISSION
    emissiveColor += Emission(i.tex.xy);
#endif
    UnityStandardData data;
    data.diffuseColor = s.diffColor;
    data.occlusion = occlusion;
    data.specularColor = s.specColor;
    data.smoothness = s.smoothness;
    data.normalWorld = s.normalWorld;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    outEmission = GBuffer_EncodeEmission(emissiveColor);
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
    outShadowMask = UnityGetRawBakedOcclusions(i.ambientOrLightmapUV.xy, IN_WORLDPOS(i));
#endif
}

#endif  // UNITY_STANDARD_CORE_PASSES_INCLUDED
