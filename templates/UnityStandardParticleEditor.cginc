// UnityStandardParticleEditor.cginc: the editor passes of Unity's Standard particle shaders:
// scene selection outline (object id and pass value) and picking (selection id), both cut out
// where the particle is transparent under the alpha test.
#ifndef UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED
#define UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED

#include "KilnParticles.cginc"
#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"

#ifdef _ALPHATEST_ON
half _Cutoff;
#endif
sampler2D _MainTex;
float4 _MainTex_ST;

float _ObjectId;
float _PassValue;
float4 _SelectionID;
uniform float _SelectionAlphaCutoff;

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING)
    float4 texcoords : TEXCOORD0;
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct VertexOutput {
    float2 texcoord : TEXCOORD0;
#ifdef _FLIPBOOK_BLENDING
    float3 texcoord2AndBlend : TEXCOORD1;
#endif
    fixed4 color : TEXCOORD2;
};

void vertEditorPass(VertexInput v, out VertexOutput o, out float4 opos : SV_POSITION) {
    UNITY_SETUP_INSTANCE_ID(v);
    opos = UnityObjectToClipPos(v.vertex);
#ifdef _FLIPBOOK_BLENDING
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
    o.color = v.color;
}

// Discards texels the alpha test removes from the visible particle.
void fragSceneClip(VertexOutput i) {
#ifdef _FLIPBOOK_BLENDING
    half alpha = ParticleFlipbookSample(_MainTex, i.texcoord, i.texcoord2AndBlend).a;
#else
    half alpha = ParticleFlipbookSample(_MainTex, i.texcoord, float3(0.0, 0.0, 0.0)).a;
#endif
    alpha *= i.color.a;
#ifdef _ALPHATEST_ON
    clip(alpha - _Cutoff);
#endif
}

half4 fragSceneHighlightPass(VertexOutput i) : SV_Target {
    fragSceneClip(i);
    return float4(_ObjectId, _PassValue, 1.0, 1.0);
}

half4 fragScenePickingPass(VertexOutput i) : SV_Target {
    fragSceneClip(i);
    return _SelectionID;
}

#endif  // UNITY_STANDARD_PARTICLE_EDITOR_INCLUDED
