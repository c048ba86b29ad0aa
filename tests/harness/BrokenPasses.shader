// Deliberately broken passes for kiln test's checks of the passes other paths draw, each bug in
// one variant. ShadowCaster: NAN_DEPTH adds NaN to the caster's depth, SHIFTED moves the caster
// sideways (its shadow is not where the object is), FLAT_DEPTH writes one depth for every texel
// (not the distance encoding the receivers read). Deferred: NAN_EMISSION writes NaN into the
// light buffer (RT3), SHORT_NORMAL writes a normal of length 0.5 into RT2.
Shader "Test/BrokenPasses"
{
    Properties
    {
        _Color ("Color", Color) = (0.8, 0.8, 0.8, 1)
        _Zero ("Zero", Float) = 0
    }

    CGINCLUDE
    #include "UnityCG.cginc"
    float4 _Color;
    float _Zero;

    struct v2f {
        float4 pos : SV_POSITION;
        float3 normal : TEXCOORD0;
    };

    v2f vert(float4 p : POSITION, float3 n : NORMAL) {
        v2f o;
        o.pos = UnityObjectToClipPos(p);
        o.normal = UnityObjectToWorldNormal(n);
        return o;
    }

    float4 base(v2f i) : SV_Target {
        return float4(_Color.rgb * saturate(normalize(i.normal).y * 0.5 + 0.5), 1);
    }

    struct GBufferOutput {
        float4 gBuffer0 : SV_Target0;
        float4 gBuffer1 : SV_Target1;
        float4 gBuffer2 : SV_Target2;
        float4 gBuffer3 : SV_Target3;
    };

    GBufferOutput gbuffer(v2f i) {
        GBufferOutput o;
        float3 n = normalize(i.normal);
    #if defined(SHORT_NORMAL)
        n *= 0.5;
    #endif
        o.gBuffer0 = float4(_Color.rgb, 1);
        o.gBuffer1 = float4(0.04, 0.04, 0.04, 0.5);
        o.gBuffer2 = float4(n * 0.5 + 0.5, 1);
        o.gBuffer3 = float4(0, 0, 0, 1);
    #if defined(NAN_EMISSION)
        o.gBuffer3.rgb += _Zero / _Zero;
    #endif
        return o;
    }

    struct v2fShadow {
        V2F_SHADOW_CASTER;
    };

    v2fShadow vertShadow(appdata_base v) {
        v2fShadow o;
        TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
    #if defined(NAN_DEPTH)
        o.pos.z += _Zero / _Zero;
    #elif defined(SHIFTED)
        o.pos.x += 0.5 * o.pos.w;
    #elif defined(FLAT_DEPTH)
        o.pos.z = 0.5 * o.pos.w;
    #endif
        return o;
    }

    float4 fragShadow(v2fShadow i) : SV_Target {
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
            #pragma vertex vert
            #pragma fragment base
            ENDCG
        }

        Pass
        {
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment gbuffer
            #pragma multi_compile _ NAN_EMISSION SHORT_NORMAL
            ENDCG
        }

        Pass
        {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            CGPROGRAM
            #pragma vertex vertShadow
            #pragma fragment fragShadow
            #pragma multi_compile_shadowcaster
            #pragma multi_compile _ NAN_DEPTH SHIFTED FLAT_DEPTH
            ENDCG
        }
    }
}
