// A geometry stage (issue 38): passes each triangle through with barycentric weights, which
// only the geometry stage computes; tests/cli/stages_test.cpp draws it.
Shader "Test/Geometry" {
    Properties { _Color ("Color", Color) = (1, 0.5, 0.25, 1) }
    SubShader { Pass {
        Tags { "LightMode" = "ForwardBase" }
        CGPROGRAM
        #pragma vertex vert
        #pragma geometry geom
        #pragma fragment frag
        #include "UnityCG.cginc"
        float4 _Color;
        struct v2g { float4 pos : SV_POSITION; float3 normal : NORMAL; };
        struct g2f { float4 pos : SV_POSITION; float3 bary : TEXCOORD0; };
        v2g vert(appdata_base v) {
            v2g o;
            o.pos = UnityObjectToClipPos(v.vertex);
            o.normal = v.normal;
            return o;
        }
        // Passes each triangle through with barycentric weights, as a wireframe shader does.
        [maxvertexcount(3)]
        void geom(triangle v2g i[3], inout TriangleStream<g2f> stream) {
            g2f o;
            o.pos = i[0].pos; o.bary = float3(1, 0, 0); stream.Append(o);
            o.pos = i[1].pos; o.bary = float3(0, 1, 0); stream.Append(o);
            o.pos = i[2].pos; o.bary = float3(0, 0, 1); stream.Append(o);
            stream.RestartStrip();
        }
        float4 frag(g2f i) : SV_Target { return _Color * float4(0.5 + 0.5 * i.bary, 1); }
        ENDCG
    } }
}
