// UnityLegacyTextureStack.cginc: Unity's texture-stack (streaming virtual texturing) API. The
// built-in pipeline has no virtual texturing and neither has Kiln: a stack is its layers sampled
// as ordinary 2D textures, so shaders written against the API compile and sample correctly.
// Layers are declared with UNITY_DECLARE_TEX2D (a texture plus sampler<name>).
#ifndef TEXTURESTACK_include
#define TEXTURESTACK_include

#if UNITY_VIRTUAL_TEXTURING
#error "virtual texturing (UNITY_VIRTUAL_TEXTURING) is not supported by Kiln; texture stacks sample their layers directly"
#endif
#define VIRTUAL_TEXTURES_ACTIVE 0

// A stack declares nothing of its own.
#define DECLARE_STACK_CB(stackName)
#define DECLARE_STACK(stackName, layer0)
#define DECLARE_STACK2(stackName, layer0, layer1)
#define DECLARE_STACK3(stackName, layer0, layer1, layer2)
#define DECLARE_STACK4(stackName, layer0, layer1, layer2, layer3)

// What a lookup needs: the UV, and the mip level for the explicit-LOD variants.
struct StackInfo {
    float2 uv;
    float lod;
};

StackInfo MakeStackInfo(float2 uv) {
    StackInfo info;
    info.uv = uv;
    info.lod = 0.0;
    return info;
}

StackInfo MakeStackInfoLod(float2 uv, float lod) {
    StackInfo info;
    info.uv = uv;
    info.lod = lod;
    return info;
}

#define PrepareStack(uv, stackName) MakeStackInfo(uv)
#define PrepareStackLod(uv, stackName, mip) MakeStackInfoLod(uv, mip)

#define SampleStack(info, texture) texture.Sample(sampler##texture, (info).uv)
#define SampleStackLod(info, texture) texture.SampleLevel(sampler##texture, (info).uv, (info).lod)
#define SampleStackNormal(info, texture, scale) \
    UnpackNormalWithScale(SampleStack(info, texture), scale)
#define SampleStackLodNormal(info, texture, scale) \
    UnpackNormalWithScale(SampleStackLod(info, texture), scale)

// No tile feedback to resolve.
#define GetResolveOutput(info) float4(1, 1, 1, 1)
#define ResolveStack(uv, stackName) float4(1, 1, 1, 1)
#define PackResolveOutput(output) output

#endif  // TEXTURESTACK_include
