// GltfTexture.cginc: a map's texture coordinates as glTF gives them, each map with its own UV
// set (TEXCOORD_0 or TEXCOORD_1) and its own KHR_texture_transform. The runtime writes a map's
// transform into <map>_ST, scale in xy and offset in zw (Unity's tiling and offset, which a
// .material file sets too), and <map>_UV: x the UV set (0 or 1), y the rotation in radians.
#ifndef KILN_GLTF_TEXTURE_INCLUDED
#define KILN_GLTF_TEXTURE_INCLUDED

// KHR_texture_transform: uv' = offset + R(rotation) (scale * uv) with R = [[cos, sin],
// [-sin, cos]], the extension's T * R * S. `uvs`: TEXCOORD_0 in xy, TEXCOORD_1 in zw. The
// transform is affine, so per fragment it equals the per-vertex result interpolated.
float2 GltfMapUV(float4 uvs, float4 st, float4 uvSetRotation) {
    float2 uv = (uvSetRotation.x > 0.5 ? uvs.zw : uvs.xy) * st.xy;
    float s, c;
    sincos(uvSetRotation.y, s, c);
    return float2(c * uv.x + s * uv.y, c * uv.y - s * uv.x) + st.zw;
}

// The coordinates of map `tex` (a sampler2D with tex_ST and tex_UV declared).
#define GLTF_MAP_UV(uvs, tex) GltfMapUV(uvs, tex##_ST, tex##_UV)

#endif  // KILN_GLTF_TEXTURE_INCLUDED
