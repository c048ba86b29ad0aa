// TerrainPreview.cginc: the terrain brush preview. It draws a procedural grid (no vertex
// buffer, one vertex per paint-context pixel) and maps paint-context pixels to heightmap UV,
// terrain-object position and brush UV through affine maps the editor sets.
#ifndef TERRAIN_PREVIEW_INCLUDED
#define TERRAIN_PREVIEW_INCLUDED

sampler2D _Heightmap;

// Paint-context pixels -> heightmap UV.
float2 _HeightmapUV_PCPixelsX;
float2 _HeightmapUV_PCPixelsY;
float2 _HeightmapUV_Offset;
float2 PaintContextPixelsToHeightmapUV(float2 pcPixels) {
    return _HeightmapUV_PCPixelsX * pcPixels.x + _HeightmapUV_PCPixelsY * pcPixels.y + _HeightmapUV_Offset;
}

// Paint-context pixels and a heightmap sample -> terrain object-space position.
float3 _ObjectPos_PCPixelsX;
float3 _ObjectPos_PCPixelsY;
float3 _ObjectPos_HeightMapSample;
float3 _ObjectPos_Offset;
float3 PaintContextPixelsToObjectPosition(float2 pcPixels, float heightmapSample) {
    return _ObjectPos_PCPixelsX * pcPixels.x + _ObjectPos_PCPixelsY * pcPixels.y +
           _ObjectPos_HeightMapSample * heightmapSample + _ObjectPos_Offset;
}

// Paint-context pixels -> brush UV.
float2 _BrushUV_PCPixelsX;
float2 _BrushUV_PCPixelsY;
float2 _BrushUV_Offset;
float2 PaintContextPixelsToBrushUV(float2 pcPixels) {
    return _BrushUV_PCPixelsX * pcPixels.x + _BrushUV_PCPixelsY * pcPixels.y + _BrushUV_Offset;
}

// Terrains are neither rotated nor scaled: object -> world is a translation. (Procedural draws
// do not set unity_ObjectToWorld, so the offset comes separately.)
float3 _TerrainObjectToWorldOffset;
float3 TerrainObjectToWorldPosition(float3 objectPosition) {
    return objectPosition + _TerrainObjectToWorldOffset;
}

// Grid position of vertex `vertexID` of a procedural quad mesh: _QuadRez.x quads per row, two
// triangles (six vertices) per quad, corners (0,0) (0,1) (1,1) / (1,1) (1,0) (0,0); scaled by
// the vertex skip _QuadRez.w.
float4 _QuadRez;  // x: quads in X, y: quads in Y, z: vertex count, w: vertex skip
float2 BuildProceduralQuadMeshVertex(uint vertexID) {
    uint quad = vertexID / 6u;
    uint corner = vertexID - quad * 6u;
    uint quadsPerRow = (uint)max(_QuadRez.x, 1.0);
    float2 quadOrigin = float2(quad % quadsPerRow, quad / quadsPerRow);
    // Corner offsets of the two triangles, bit i of each mask is corner i's x (or y).
    const uint xMask = 0x1Cu;  // corners 2, 3, 4
    const uint yMask = 0x0Eu;  // corners 1, 2, 3
    float2 offset = float2((xMask >> corner) & 1u, (yMask >> corner) & 1u);
    return (quadOrigin + offset) * _QuadRez.w;
}

// Antialiased stripe of `pixelWidth` screen pixels where x crosses stripeX: the distance in x
// is converted to pixels with the screen-space gradient of x.
float Stripe(in float x, in float stripeX, in float pixelWidth) {
    float pixelsPerUnit = 1.0 / max(length(float2(ddx(x), ddy(x))), 1e-5);
    return saturate(0.5 + 0.5 * (0.5 * pixelWidth - pixelsPerUnit * abs(x - stripeX)));
}

#endif  // TERRAIN_PREVIEW_INCLUDED
