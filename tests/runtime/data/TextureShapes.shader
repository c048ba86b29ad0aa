// TextureShapes: samples textures of every shape the runtime binds defaults for (3D, cube, 2D
// array) and the engine's environment cube, to check that each gets an image view of its own
// shape (the validation layer rejects a 2D view bound to a cube) and the documented value.
//   default:            (3D "black".r, cube "white".g, 2D-array "gray".b, 1)
//   _SHOW_ENVIRONMENT:  DecodeHDR(unity_SpecCube0) in the normal's direction (the ambient sky)
//   _SHOW_MIRROR:       unity_WorldTransformParams.w * 0.5 + 0.5 (0 for a mirroring transform)
Shader "KilnTest/TextureShapes"
{
    Properties
    {
        _Volume ("Volume", 3D) = "black" {}
        _Cube ("Cube", Cube) = "white" {}
        _Layers ("Layers", 2DArray) = "gray" {}
    }
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma shader_feature _ _SHOW_ENVIRONMENT _SHOW_MIRROR
            #include "UnityCG.cginc"

            sampler3D _Volume;
            samplerCUBE _Cube;
            UNITY_DECLARE_TEX2DARRAY(_Layers);

            struct v2f {
                float4 pos : SV_POSITION;
                float3 normal : TEXCOORD0;
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.normal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            float4 frag(v2f i) : SV_Target {
            #if defined(_SHOW_ENVIRONMENT)
                half4 probe = UNITY_SAMPLE_TEXCUBE(unity_SpecCube0, normalize(i.normal));
                return float4(DecodeHDR(probe, unity_SpecCube0_HDR), 1.0);
            #elif defined(_SHOW_MIRROR)
                return float4(unity_WorldTransformParams.www * 0.5 + 0.5, 1.0);
            #else
                float r = tex3D(_Volume, float3(0.5, 0.5, 0.5)).r;
                float g = texCUBE(_Cube, normalize(i.normal)).g;
                float b = UNITY_SAMPLE_TEX2DARRAY(_Layers, float3(0.5, 0.5, 0.0)).b;
                return float4(r, g, b, 1.0);
            #endif
            }
            ENDCG
        }
    }
}
