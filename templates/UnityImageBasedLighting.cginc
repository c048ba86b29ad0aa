// UnityImageBasedLighting.cginc: reflection-probe lookups with Unity's names (roughness ->
// cubemap mip), and the reference integrators of image-based lighting by importance sampling
// (Karis 2013, "Real Shading in Unreal Engine 4"; Lagarde and de Rousiers 2014) that Unity
// ships for ground-truth comparisons.
#ifndef UNITY_IMAGE_BASED_LIGHTING_INCLUDED
#define UNITY_IMAGE_BASED_LIGHTING_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardBRDF.cginc"

struct Unity_GlossyEnvironmentData {
    half roughness;  // perceptual roughness, 1 - smoothness (not squared)
    half3 reflUVW;   // direction to look up
};

Unity_GlossyEnvironmentData UnityGlossyEnvironmentSetup(half Smoothness, half3 worldViewDir,
                                                        half3 Normal, half3 fresnel0) {
    Unity_GlossyEnvironmentData g;
    g.roughness = SmoothnessToPerceptualRoughness(Smoothness);
    g.reflUVW = reflect(-worldViewDir, Normal);
    return g;
}

// Perceptual roughness -> mip of a probe prefiltered with GGX, r (1.7 - 0.7 r) x steps (a fit
// that keeps the low mips for smooth surfaces), and back.
half perceptualRoughnessToMipmapLevel(half perceptualRoughness) {
    return perceptualRoughness * (1.7 - 0.7 * perceptualRoughness) * UNITY_SPECCUBE_LOD_STEPS;
}
half mipmapLevelToPerceptualRoughness(half mipmapLevel) {
    half m = mipmapLevel / UNITY_SPECCUBE_LOD_STEPS;
    // inverse of r (1.7 - 0.7 r) = m on [0, 1]
    return saturate(1.7 / 1.4 - sqrt(max(2.89 / 1.96 - m / 0.7, 0.0)));
}

// Prefiltered radiance from a reflection probe, HDR-decoded.
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr,
                              Unity_GlossyEnvironmentData glossIn) {
    half mip = perceptualRoughnessToMipmapLevel(glossIn.roughness);
    half4 rgbm = UNITY_SAMPLE_TEXCUBE_LOD(tex, glossIn.reflUVW, mip);
    return DecodeHDR(rgbm, hdr);
}

// Unity 5.0's lookup by normal and roughness (kept for old shaders).
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr, half3 worldNormal,
                              half perceptualRoughness) {
    Unity_GlossyEnvironmentData g;
    g.roughness = perceptualRoughness;
    g.reflUVW = worldNormal;
    return Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(tex), hdr, g);
}

// ---- reference integration ----
// Van der Corput radical inverse in base 2 and the Hammersley point set.
float RadicalInverse_VdC(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10;  // / 2^32
}
float2 Hammersley2d(uint i, uint maxSampleCount) {
    return float2(float(i) / float(maxSampleCount), RadicalInverse_VdC(i));
}
// Integer hash to [0, 1) (Wang hash).
float Hash(uint s) {
    s = s ^ 2747636419u;
    s = s * 2654435769u;
    s = s ^ (s >> 16);
    s = s * 2654435769u;
    s = s ^ (s >> 16);
    s = s * 2654435769u;
    return float(s) / 4294967295.0;
}
float2 InitRandom(float2 input) {
    float2 r;
    r.x = Hash(uint(input.x * 4294967295.0));
    r.y = Hash(uint(input.y * 4294967295.0));
    return r;
}

// An orthonormal frame around N (Frisvad 2012, with the singularity at N.z = -1 handled).
void GetLocalFrame(float3 N, out float3 tangentX, out float3 tangentY) {
    float3 up = abs(N.z) < 0.999 ? float3(0.0, 0.0, 1.0) : float3(1.0, 0.0, 0.0);
    tangentX = normalize(cross(up, N));
    tangentY = cross(N, tangentX);
}

// Cosine-weighted hemisphere direction around N: pdf = n.l / pi.
void ImportanceSampleCosDir(float2 u, float3 N, float3 tangentX, float3 tangentY, out float3 L) {
    float cosTheta = sqrt(max(0.0, 1.0 - u.x));
    float sinTheta = sqrt(u.x);
    float phi = KILN_PI * 2.0 * u.y;
    L = normalize(tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) +
                  cosTheta * N);
}
// GGX-distributed half vector (Walter et al. 2007, eqs. 35-36).
void ImportanceSampleGGXDir(float2 u, float3 V, float3 N, float3 tangentX, float3 tangentY,
                            float roughness, out float3 H, out float3 L) {
    float a2 = roughness * roughness;
    float cosThetaH = sqrt((1.0 - u.x) / (1.0 + (a2 - 1.0) * u.x));
    float sinThetaH = sqrt(max(0.0, 1.0 - cosThetaH * cosThetaH));
    float phiH = KILN_PI * 2.0 * u.y;
    H = normalize(tangentX * (sinThetaH * cos(phiH)) + tangentY * (sinThetaH * sin(phiH)) +
                  cosThetaH * N);
    L = 2.0 * dot(V, H) * H - V;
}
void ImportanceSampleLambert(float2 u, float3 N, float3 tangentX, float3 tangentY,
                             out float3 L, out float NdotL, out float weightOverPdf) {
    ImportanceSampleCosDir(u, N, tangentX, tangentY, L);
    NdotL = saturate(dot(N, L));
    weightOverPdf = 1.0;  // the cosine cancels against the pdf (the 1/pi is Kiln's convention)
}
void ImportanceSampleGGX(float2 u, float3 V, float3 N, float3 tangentX, float3 tangentY,
                         float roughness, float NdotV, out float3 L, out float VdotH,
                         out float NdotL, out float weightOverPdf) {
    float3 H;
    ImportanceSampleGGXDir(u, V, N, tangentX, tangentY, roughness, H, L);
    float NdotH = saturate(dot(N, H));
    VdotH = saturate(dot(V, H));
    NdotL = saturate(dot(N, L));
    // weight / pdf = 4 V (v.h) (n.l) / (n.h) for the height-correlated visibility V
    float Vis = V_SmithGGXCorrelated(NdotV, NdotL, roughness);
    weightOverPdf = 4.0 * Vis * NdotL * VdotH / max(NdotH, 1e-5);
}

// Reference irradiance, Disney diffuse and GGX specular from a cube map, by Monte Carlo.
void IntegrateLambertDiffuseIBLRef(out float3 diffuseLighting, UNITY_ARGS_TEXCUBE(tex),
                                   float4 texHdrParam, float3 N, float3 diffuseColor,
                                   uint sampleCount = 2048) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float3 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 L;
        float NdotL, weightOverPdf;
        ImportanceSampleLambert(Hammersley2d(i, sampleCount), N, tangentX, tangentY, L, NdotL,
                                weightOverPdf);
        if (NdotL > 0.0)
            acc += DecodeHDR(UNITY_SAMPLE_TEXCUBE_LOD(tex, L, 0), texHdrParam) * weightOverPdf;
    }
    diffuseLighting = diffuseColor * acc / sampleCount;
}
void IntegrateDisneyDiffuseIBLRef(out float3 diffuseLighting, UNITY_ARGS_TEXCUBE(tex),
                                  float4 texHdrParam, float3 N, float3 V, float roughness,
                                  float3 diffuseColor, uint sampleCount = 2048) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float NdotV = max(dot(N, V), 1e-5);
    float3 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 L;
        float NdotL, weightOverPdf;
        ImportanceSampleLambert(Hammersley2d(i, sampleCount), N, tangentX, tangentY, L, NdotL,
                                weightOverPdf);
        if (NdotL > 0.0) {
            float LdotH = saturate(dot(L, normalize(L + V)));
            float disney = DisneyDiffuse(NdotV, NdotL, LdotH, RoughnessToPerceptualRoughness(roughness));
            acc += DecodeHDR(UNITY_SAMPLE_TEXCUBE_LOD(tex, L, 0), texHdrParam) * disney *
                   weightOverPdf;
        }
    }
    diffuseLighting = diffuseColor * acc / sampleCount;
}
void IntegrateSpecularGGXIBLRef(out float3 specularLighting, UNITY_ARGS_TEXCUBE(tex),
                                float4 texHdrParam, float3 N, float3 V, float roughness,
                                float3 f0, float3 f90, uint sampleCount = 2048) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float NdotV = max(dot(N, V), 1e-5);
    float3 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 L;
        float VdotH, NdotL, weightOverPdf;
        ImportanceSampleGGX(Hammersley2d(i, sampleCount), V, N, tangentX, tangentY, roughness,
                            NdotV, L, VdotH, NdotL, weightOverPdf);
        if (NdotL > 0.0) {
            float3 F = F_SchlickLerp(f0, f90, VdotH);
            acc += DecodeHDR(UNITY_SAMPLE_TEXCUBE_LOD(tex, L, 0), texHdrParam) * F * weightOverPdf;
        }
    }
    specularLighting = acc / sampleCount;
}

// Pre-integrated specular and diffuse terms: x = scale of f0, y = bias (Karis 2013, eq. 8), z =
// Disney diffuse; by importance sampling.
float4 IntegrateDFG(float3 V, float3 N, float roughness, uint sampleCount) {
    float NdotV = saturate(dot(N, V));
    float4 acc = 0;
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    for (uint i = 0; i < sampleCount; ++i) {
        float2 u = Hammersley2d(i, sampleCount);
        float3 L;
        float VdotH, NdotL, weightOverPdf;
        ImportanceSampleGGX(u, V, N, tangentX, tangentY, roughness, NdotV, L, VdotH, NdotL,
                            weightOverPdf);
        if (NdotL > 0.0) {
            float Fc = Pow5(1.0 - VdotH);
            acc.x += (1.0 - Fc) * weightOverPdf;
            acc.y += Fc * weightOverPdf;
        }
        ImportanceSampleCosDir(u, N, tangentX, tangentY, L);
        NdotL = saturate(dot(N, L));
        if (NdotL > 0.0) {
            float LdotH = saturate(dot(L, normalize(V + L)));
            acc.z += DisneyDiffuse(NdotV, NdotL, LdotH, RoughnessToPerceptualRoughness(roughness));
        }
    }
    return acc / sampleCount;
}

// Prefiltered radiance for one roughness, the split-sum left half (Karis 2013, eq. 7), with the
// sample's mip chosen from its solid angle (GPU Gems 3, chapter 20).
float4 IntegrateLD(UNITY_ARGS_TEXCUBE(tex), float3 V, float3 N, float roughness, float mipmapcount,
                   float invOmegaP, uint sampleCount, bool prefilter = true) {
    float3 acc = 0;
    float accWeight = 0;
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    for (uint i = 0; i < sampleCount; ++i) {
        float3 H, L;
        ImportanceSampleGGXDir(Hammersley2d(i, sampleCount), V, N, tangentX, tangentY, roughness,
                               H, L);
        float NdotL = saturate(dot(N, L));
        float mip = 0;
        if (prefilter) {
            float NdotH = saturate(dot(N, H));
            float pdf = D_GGX(NdotH, roughness) * 0.25;
            float omegaS = 1.0 / (sampleCount * max(pdf, 1e-7));
            mip = clamp(0.5 * log2(omegaS * invOmegaP), 0, mipmapcount);
        }
        if (NdotL > 0.0) {
            acc += UNITY_SAMPLE_TEXCUBE_LOD(tex, L, mip).rgb * NdotL;
            accWeight += NdotL;
        }
    }
    return float4(acc / max(accWeight, 1e-7), 1.0);
}

#endif  // UNITY_IMAGE_BASED_LIGHTING_INCLUDED
