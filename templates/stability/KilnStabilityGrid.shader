// kiln stability's grid harness (docs/accuracy.md, "kiln stability"): each pixel evaluates one
// point of an adversarial input grid through the library's own functions, so the GPU result can
// be compared with the CPU double-precision reference (kiln/reference). Not a material: the
// runtime fills every property (kiln/runtime/template_stability.h owns the grids).
//
// Pixel i = y * _Grid.x + x is grid point (a, b, c, d), a varying fastest; axis k's value j is
// component j of _Axis{k}Lo (j < 4) or _Axis{k}Hi (j >= 4). _Grid = (image width, points, case).
Shader "Hidden/Kiln/StabilityGrid"
{
    Properties
    {
        _Grid ("Width, points, case", Vector) = (1, 0, 0, 0)
        _Counts ("Values per axis", Vector) = (1, 1, 1, 1)
        _Axis0Lo ("Axis 0, values 0-3", Vector) = (0, 0, 0, 0)
        _Axis0Hi ("Axis 0, values 4-7", Vector) = (0, 0, 0, 0)
        _Axis1Lo ("Axis 1, values 0-3", Vector) = (0, 0, 0, 0)
        _Axis1Hi ("Axis 1, values 4-7", Vector) = (0, 0, 0, 0)
        _Axis2Lo ("Axis 2, values 0-3", Vector) = (0, 0, 0, 0)
        _Axis2Hi ("Axis 2, values 4-7", Vector) = (0, 0, 0, 0)
        _Axis3Lo ("Axis 3, values 0-3", Vector) = (0, 0, 0, 0)
        _Axis3Hi ("Axis 3, values 4-7", Vector) = (0, 0, 0, 0)
        _SHr ("SH L0-L1 red", Vector) = (0, 0, 0, 0)
        _SHg ("SH L0-L1 green", Vector) = (0, 0, 0, 0)
        _SHb ("SH L0-L1 blue", Vector) = (0, 0, 0, 0)
        _SHBr ("SH L2 red", Vector) = (0, 0, 0, 0)
        _SHBg ("SH L2 green", Vector) = (0, 0, 0, 0)
        _SHBb ("SH L2 blue", Vector) = (0, 0, 0, 0)
        _SHCc ("SH L2 (x^2 - y^2)", Vector) = (0, 0, 0, 0)
    }
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex GridVertex
            #pragma fragment GridFragment
            // KilnBRDF.cginc first, so a planted copy in an -I folder or --templates is the one
            // every later include sees (its include guard keeps the shipped one out).
            #include "KilnBRDF.cginc"
            #include "KilnAttenuation.cginc"
            #include "KilnClassicLighting.cginc"
            #include "KilnSH.cginc"
            #include "UnityStandardBRDF.cginc"

            float4 _Grid, _Counts;
            float4 _Axis0Lo, _Axis0Hi, _Axis1Lo, _Axis1Hi, _Axis2Lo, _Axis2Hi, _Axis3Lo, _Axis3Hi;
            float4 _SHr, _SHg, _SHb, _SHBr, _SHBg, _SHBb, _SHCc;

            float4 GridVertex(float4 vertex : POSITION) : SV_POSITION {
                return UnityObjectToClipPos(vertex.xyz);
            }

            float AxisValue(float4 lo, float4 hi, uint j) {
                return j < 4 ? lo[j] : hi[j - 4];
            }

            // A unit vector at cosine c to +z and azimuth phi.
            float3 WithCosine(float c, float phi) {
                float s = sqrt(max(0.0, 1.0 - c * c));
                return float3(s * cos(phi), s * sin(phi), c);
            }

            // The light-direction axis: a cosine in [-1, 1] at azimuth 2, or 2: l = v, 3: l = -v,
            // 4: the zero vector, 5: a denormal vector.
            float3 LightDirection(float code, float3 v) {
                if (code <= 1.0) return WithCosine(code, 2.0);
                if (code == 2.0) return v;
                if (code == 3.0) return -v;
                if (code == 4.0) return float3(0.0, 0.0, 0.0);
                return float3(1e-40, 0.0, 1e-40);
            }

            // The normal axis of the SH case: a cosine, or 2: zero, 3: denormal.
            float3 NormalFor(float code, float phi) {
                if (code <= 1.0) return WithCosine(code, phi);
                if (code == 2.0) return float3(0.0, 0.0, 0.0);
                return float3(1e-40, 0.0, 1e-40);
            }

            float4 Evaluate(uint kase, float a, float b, float c, float d) {
                const float3 n = float3(0.0, 0.0, 1.0);
                if (kase == 0) {  // BRDF1: a = n . v, b = light, c = perceptual roughness, d = C
                    float3 v = WithCosine(a, 0.0);
                    UnityLight light;
                    light.dir = LightDirection(b, v);
                    light.color = float3(d, d, d);
                    light.ndotl = 0.0;
                    UnityIndirect gi;
                    gi.diffuse = float3(0.1, 0.1, 0.1);
                    gi.specular = float3(0.1, 0.1, 0.1);
                    return BRDF1_Unity_PBS(float3(0.5, 0.5, 0.5), float3(0.5, 0.5, 0.5), 0.5,
                                           1.0 - c, n, v, light, gi);
                }
                if (kase == 1) {  // GGX terms: a = n . h and n . v, b = n . l, c = perceptual r.
                    float r = PerceptualRoughnessToRoughness(c);
                    return float4(D_GGX(a, r), V_SmithGGXCorrelated(max(a, 1e-5), b, r),
                                  F_Schlick(float3(0.04, 0.04, 0.04), a).r, 1.0);
                }
                if (kase == 2) {  // BRDF choices: as case 1, through the alternatives
                    float r = PerceptualRoughnessToRoughness(c);
                    return float4(D_BlinnPhong(a, r), V_SmithGGXCorrelatedFast(max(a, 1e-5), b, r),
                                  F_Exact(float3(0.04, 0.04, 0.04), a).r, 1.0);
                }
                if (kase == 3) {  // Blinn-Phong: a = n . v, b = light, c = exponent, d = C
                    float3 v = WithCosine(a, 0.0);
                    float3 l = LightDirection(b, v);
                    float3 color = float3(d, d, d);
                    float3 h = BlinnPhong_HalfVector(l, v);
                    return float4(BlinnPhong_Specular(float3(1, 1, 1), color, n, h, c).r,
                                  Lambert_Diffuse(float3(1, 1, 1), color, n, l).g, 0.0, 1.0);
                }
                if (kase == 4) {  // distance: a = distance, b = 1 / range^2
                    float d2 = a * a;
                    return float4(Attenuation_Distance(d2, b), Attenuation_InverseSquare(d2),
                                  Attenuation_RangeWindow(d2, b), 1.0);
                }
                if (kase == 5) {  // spot: a = cosine to the axis, b = cos outer, c = cos inner
                    float3 l = -WithCosine(a, 1.0);
                    return float4(Attenuation_SpotCone(l, float3(0.0, 0.0, 1.0), b, c), 0.0, 0.0,
                                  1.0);
                }
                if (kase == 7) {  // Unity's half terms: a = n . v, b = n . l, c = perceptual r.,
                                  // d = l . h; binary16 arithmetic in a --precision half build
                    half r = PerceptualRoughnessToRoughness(c);
                    return float4(DisneyDiffuse(a, b, d, c), SmithBeckmannVisibilityTerm(b, a, r),
                                  FresnelTerm(half3(0.04, 0.04, 0.04), d).r, 1.0);
                }
                // SH: a = normal, b = its azimuth, c = scale of the coefficients
                float3 e = SH_Irradiance(_SHr * c, _SHg * c, _SHb * c, _SHBr * c, _SHBg * c,
                                         _SHBb * c, _SHCc * c, NormalFor(a, b));
                return float4(e, 1.0);
            }

            float4 GridFragment(float4 pos : SV_Position) : SV_Target {
                uint width = uint(_Grid.x);
                uint i = uint(pos.y) * width + uint(pos.x);
                if (i >= uint(_Grid.y)) {
                    return float4(0.0, 0.0, 0.0, 1.0);
                }
                uint4 count = uint4(_Counts);
                uint ja = i % count.x;
                uint jb = (i / count.x) % count.y;
                uint jc = (i / (count.x * count.y)) % count.z;
                uint jd = i / (count.x * count.y * count.z);
                return Evaluate(uint(_Grid.z), AxisValue(_Axis0Lo, _Axis0Hi, ja),
                                AxisValue(_Axis1Lo, _Axis1Hi, jb),
                                AxisValue(_Axis2Lo, _Axis2Hi, jc),
                                AxisValue(_Axis3Lo, _Axis3Hi, jd));
            }
            ENDCG
        }
    }
}
