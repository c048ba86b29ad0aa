// UnitySprites.cginc: the sprite vertex and fragment programs of Unity's Sprites shaders, with
// Unity's names: flip, renderer colour times material colour, optional pixel snapping and an
// external alpha texture (ETC1_EXTERNAL_ALPHA), premultiplied output.
#ifndef UNITY_SPRITES_INCLUDED
#define UNITY_SPRITES_INCLUDED

#include "UnityCG.cginc"

CBUFFER_START(UnityPerDrawSprite)
    fixed4 _RendererColor;
    fixed2 _Flip;
    float _EnableExternalAlpha;
CBUFFER_END

fixed4 _Color;

struct appdata_t {
    float4 vertex : POSITION;
    float4 color : COLOR;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct v2f {
    float4 vertex : SV_POSITION;
    fixed4 color : COLOR;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};

inline float4 UnityFlipSprite(in float3 pos, in fixed2 flip) {
    return float4(pos.xy * flip, pos.z, 1.0);
}

v2f SpriteVert(appdata_t IN) {
    v2f OUT;
    UNITY_SETUP_INSTANCE_ID(IN);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(OUT);
    OUT.vertex = UnityObjectToClipPos(UnityFlipSprite(IN.vertex.xyz, _Flip));
    OUT.texcoord = IN.texcoord;
    OUT.color = IN.color * _Color * _RendererColor;
#ifdef PIXELSNAP_ON
    OUT.vertex = UnityPixelSnap(OUT.vertex);
#endif
    return OUT;
}

sampler2D _MainTex;
sampler2D _AlphaTex;

fixed4 SampleSpriteTexture(float2 uv) {
    fixed4 color = tex2D(_MainTex, uv);
#if ETC1_EXTERNAL_ALPHA
    color.a = lerp(color.a, tex2D(_AlphaTex, uv).r, _EnableExternalAlpha);
#endif
    return color;
}

fixed4 SpriteFrag(v2f IN) : SV_Target {
    fixed4 c = SampleSpriteTexture(IN.texcoord) * IN.color;
    c.rgb *= c.a;
    return c;
}

#endif  // UNITY_SPRITES_INCLUDED
