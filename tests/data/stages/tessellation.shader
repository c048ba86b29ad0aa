// Tessellation stages (issue 38), written as Unity's tessellation examples are: a hull shader
// with a patch-constant function and a domain shader. The colour is the domain location, which
// only the domain stage has; tests/cli/stages_test.cpp draws it.
Shader "Test/Tessellation" {
    Properties { _Tess ("Tessellation", Range(1, 16)) = 4  _Color ("Color", Color) = (0.25, 0.5, 1, 1) }
    SubShader { Pass {
        Tags { "LightMode" = "ForwardBase" }
        CGPROGRAM
        #pragma vertex vert
        #pragma hull hull
        #pragma domain domain
        #pragma fragment frag
        #include "UnityCG.cginc"
        float _Tess;
        float4 _Color;
        struct appdata { float4 vertex : POSITION; float3 normal : NORMAL; };
        struct ControlPoint { float4 vertex : INTERNALTESSPOS; float3 normal : NORMAL; };
        struct TessFactors { float edge[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
        struct v2f { float4 pos : SV_POSITION; float3 bary : TEXCOORD0; };
        ControlPoint vert(appdata v) {
            ControlPoint o;
            o.vertex = v.vertex;
            o.normal = v.normal;
            return o;
        }
        TessFactors patchConstant(InputPatch<ControlPoint, 3> patch) {
            TessFactors f;
            f.edge[0] = _Tess; f.edge[1] = _Tess; f.edge[2] = _Tess;
            f.inside = _Tess;
            return f;
        }
        [UNITY_domain("tri")]
        [UNITY_outputcontrolpoints(3)]
        [UNITY_outputtopology("triangle_cw")]
        [UNITY_partitioning("integer")]
        [UNITY_patchconstantfunc("patchConstant")]
        ControlPoint hull(InputPatch<ControlPoint, 3> patch, uint id : SV_OutputControlPointID) {
            return patch[id];
        }
        [UNITY_domain("tri")]
        v2f domain(TessFactors f, OutputPatch<ControlPoint, 3> patch, float3 bary : SV_DomainLocation) {
            v2f o;
            float4 p = patch[0].vertex * bary.x + patch[1].vertex * bary.y + patch[2].vertex * bary.z;
            o.pos = UnityObjectToClipPos(p);
            o.bary = bary;  // only the domain stage has it
            return o;
        }
        float4 frag(v2f i) : SV_Target { return float4(i.bary, 1) * _Color.a; }
        ENDCG
    } }
}
