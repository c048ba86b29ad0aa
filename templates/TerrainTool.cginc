// TerrainTool.cginc: coordinate maps of Unity's terrain paint tools. A paint context is the
// rectangle of heightmap texels a brush stroke edits; the editor sets the affine maps below.
#ifndef TERRAIN_TOOL_INCLUDED
#define TERRAIN_TOOL_INCLUDED

float4 _PCUVToBrushUVScales;  // xy: brush UV per paint-context u, zw: per v
float2 _PCUVToBrushUVOffset;

// Paint-context UV -> brush UV (an affine map).
float2 PaintContextUVToBrushUV(float2 pcUV) {
    return _PCUVToBrushUVScales.xy * pcUV.x + _PCUVToBrushUVScales.zw * pcUV.y + _PCUVToBrushUVOffset;
}

// The paint context covers the heightmap one to one.
float2 PaintContextUVToHeightmapUV(float2 pcUV) {
    return pcUV;
}

#endif  // TERRAIN_TOOL_INCLUDED
