// UnityColorGamut.cginc: display transfer functions and the simple HDR display mapping Unity's
// blit shaders use, with Unity's names: sRGB (IEC 61966-2-1), ST 2084 / PQ (SMPTE ST 2084:2014),
// gamma 2.2, and Rec. 709 -> Rec. 2020 / P3 primaries.
#ifndef UNITY_COLOR_GAMUT_INCLUDED
#define UNITY_COLOR_GAMUT_INCLUDED

#include "KilnColor.cginc"

#define kColorGamutSRGB 0
#define kColorGamutRec709 1
#define kColorGamutRec2020 2
#define kColorGamutDisplayP3 3
#define kColorGamutHDR10 4
#define kColorGamutDolbyHDR 5
#define kColorGamutP3D65G22 6
#define kReferenceLuminanceWhiteForRec709 80  // nits of SDR white (sRGB reference display)

float3 LinearToSRGB(float3 color) {
    return LinearToSrgb(color);
}
float3 SRGBToLinear(float3 color) {
    return SrgbToLinear(color);
}

// SMPTE ST 2084 (PQ) constants, eq. 5.
#define PQ_M1 (2610.0 / 4096.0 / 4)
#define PQ_M2 (2523.0 / 4096.0 * 128)
#define PQ_C1 (3424.0 / 4096.0)
#define PQ_C2 (2413.0 / 4096.0 * 32)
#define PQ_C3 (2392.0 / 4096.0 * 32)
// Linear light in units of 10000 nits -> PQ code value.
float3 LinearToST2084(float3 color) {
    float3 cp = pow(max(color, 0.0), PQ_M1);
    return pow((PQ_C1 + PQ_C2 * cp) / (1 + PQ_C3 * cp), PQ_M2);
}
float3 ST2084ToLinear(float3 color) {
    float3 x = pow(max(color, 0.0), 1.0 / PQ_M2);
    // guard: code values above the PQ range make the denominator reach 0
    return pow(max(x - PQ_C1, 0) / max(PQ_C2 - PQ_C3 * x, 1e-7), 1.0 / PQ_M1);
}
float3 LinearToGamma22(float3 color) {
    return pow(abs(color.rgb), 1.0 / 2.2);
}
float3 Gamma22ToLinear(float3 color) {
    return pow(abs(color.rgb), 2.2);
}

// Rec. 709 primaries <-> Rec. 2020 and -> Display P3 (ITU-R BT.2087-0; SMPTE EG 432-1).
static const float3x3 kRec709ToRec2020 = {0.627402, 0.329292, 0.043306,
                                          0.069095, 0.919544, 0.011360,
                                          0.016394, 0.088028, 0.895578};
static const float3x3 kRec2020ToRec709 = {1.660491, -0.587641, -0.072850,
                                          -0.124550, 1.132900, -0.008349,
                                          -0.018151, -0.100579, 1.118730};
static const float3x3 kRec709ToP3D65 = {0.822462, 0.177538, 0.000000,
                                        0.033194, 0.966806, 0.000000,
                                        0.017083, 0.072397, 0.910520};

// Scene-referred linear Rec. 709 -> the display's signal: sRGB/709 encoded, or PQ in Rec. 2020
// with paper white at nitsForPaperWhite and a soft clip at maxDisplayNits, or gamma 2.2 P3.
float3 SimpleHDRDisplayToneMapAndOETF(float3 scene, int colorGamut, bool forceGammaToLinear,
                                      float nitsForPaperWhite, float maxDisplayNits) {
    float3 result = forceGammaToLinear ? SRGBToLinear(scene) : scene;
    if (colorGamut == kColorGamutSRGB || colorGamut == kColorGamutRec709) {
        return LinearToSRGB(result);
    }
    if (colorGamut == kColorGamutHDR10 || colorGamut == kColorGamutDolbyHDR ||
        colorGamut == kColorGamutRec2020) {
        float3 nits = mul(kRec709ToRec2020, result) * nitsForPaperWhite;
        nits = min(nits, maxDisplayNits);
        return LinearToST2084(nits / 10000.0);
    }
    if (colorGamut == kColorGamutP3D65G22 || colorGamut == kColorGamutDisplayP3) {
        float3 p3 = mul(kRec709ToP3D65, result) * (nitsForPaperWhite / maxDisplayNits);
        return LinearToGamma22(p3);
    }
    return result;
}
float3 InverseSimpleHDRDisplayToneMapAndOETF(float3 result, int colorGamut,
                                             bool forceGammaToLinear, float nitsForPaperWhite,
                                             float maxDisplayNits) {
    float3 scene = result;
    if (colorGamut == kColorGamutSRGB || colorGamut == kColorGamutRec709) {
        scene = SRGBToLinear(result);
    } else if (colorGamut == kColorGamutHDR10 || colorGamut == kColorGamutDolbyHDR ||
               colorGamut == kColorGamutRec2020) {
        float3 nits = ST2084ToLinear(result) * 10000.0;
        scene = mul(kRec2020ToRec709, nits / nitsForPaperWhite);
    } else if (colorGamut == kColorGamutP3D65G22 || colorGamut == kColorGamutDisplayP3) {
        scene = Gamma22ToLinear(result) * (maxDisplayNits / nitsForPaperWhite);
    }
    return forceGammaToLinear ? LinearToSRGB(scene) : scene;
}

#endif  // UNITY_COLOR_GAMUT_INCLUDED
