// KilnColor.cginc: colour-space transfer functions and luminance.
#ifndef KILN_COLOR_INCLUDED
#define KILN_COLOR_INCLUDED

#include "KilnCommon.cginc"

// sRGB electro-optical transfer (IEC 61966-2-1:1999, eq. for R'sRGB -> R): encoded -> linear.
float3 SrgbToLinear(float3 c) {
    // guard: pow of a negative base is undefined; the transfer is defined on [0, 1] and extended
    // linearly below 0 by clamping
    c = max(c, 0.0);
    float3 lo = c / 12.92;
    float3 hi = pow((c + 0.055) / 1.055, 2.4);
    return lerp(hi, lo, step(c, 0.04045));
}

// Inverse sRGB transfer (IEC 61966-2-1:1999): linear -> encoded.
float3 LinearToSrgb(float3 c) {
    // guard: pow(0, 1/2.4) is fine but pow of a negative base is not
    c = max(c, 0.0);
    float3 lo = c * 12.92;
    float3 hi = 1.055 * pow(max(c, 1e-30), 1.0 / 2.4) - 0.055;
    return lerp(hi, lo, step(c, 0.0031308));
}

// Relative luminance of linear Rec. 709 primaries (ITU-R BT.709-6, item 3.3).
float LuminanceRec709(float3 linearRgb) {
    return dot(linearRgb, float3(0.2126, 0.7152, 0.0722));
}

#endif  // KILN_COLOR_INCLUDED
