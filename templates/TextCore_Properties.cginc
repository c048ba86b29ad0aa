// TextCore_Properties.cginc: the material properties of Unity's TextCore signed-distance-field
// text shaders, declared as plain uniforms (the shader's Properties block gives their defaults).
// TextCoreProperties.cginc is the same list under the older file name.
#ifndef KILN_TEXTCORE_PROPERTIES_INCLUDED
#define KILN_TEXTCORE_PROPERTIES_INCLUDED

// Face: the glyph interior.
uniform sampler2D _FaceTex;
uniform float _FaceUVSpeedX;
uniform float _FaceUVSpeedY;
uniform fixed4 _FaceColor;
uniform float _FaceDilate;        // distance offset of the edge, [0, 1]
uniform float _OutlineSoftness;   // [0, 1]

// Outline.
uniform sampler2D _OutlineTex;
uniform float _OutlineUVSpeedX;
uniform float _OutlineUVSpeedY;
uniform fixed4 _OutlineColor;
uniform float _OutlineWidth;      // [0, 1]

// Bevel and bump.
uniform float _Bevel;
uniform float _BevelOffset;
uniform float _BevelWidth;
uniform float _BevelClamp;
uniform float _BevelRoundness;
uniform sampler2D _BumpMap;
uniform float _BumpOutline;
uniform float _BumpFace;

// Environment reflection.
uniform samplerCUBE _Cube;
uniform fixed4 _ReflectFaceColor;
uniform fixed4 _ReflectOutlineColor;
uniform float3 _EnvMatrixRotation;
uniform float4x4 _EnvMatrix;

// Lighting.
uniform fixed4 _SpecularColor;
uniform float _LightAngle;        // radians
uniform float _SpecularPower;
uniform float _Reflectivity;
uniform float _Diffuse;
uniform float _Ambient;

// Underlay (drop shadow).
uniform fixed4 _UnderlayColor;
uniform float _UnderlayOffsetX;
uniform float _UnderlayOffsetY;
uniform float _UnderlayDilate;
uniform float _UnderlaySoftness;

// Glow.
uniform fixed4 _GlowColor;
uniform float _GlowOffset;
uniform float _GlowOuter;
uniform float _GlowInner;
uniform float _GlowPower;

// Set by the text API rather than the material inspector.
uniform float _ShaderFlags;
uniform float _WeightNormal;
uniform float _WeightBold;
uniform float _ScaleRatioA;
uniform float _ScaleRatioB;
uniform float _ScaleRatioC;
uniform float _VertexOffsetX;
uniform float _VertexOffsetY;

// Masking and clipping.
uniform float _MaskID;
uniform sampler2D _MaskTex;
uniform float4 _MaskCoord;
uniform float4 _ClipRect;         // xy: lower-left corner, zw: upper-right corner
uniform float _MaskSoftnessX;
uniform float _MaskSoftnessY;

// The font atlas.
uniform sampler2D _MainTex;
uniform float _TextureWidth;
uniform float _TextureHeight;
uniform float _GradientScale;     // distance range encoded in the atlas, in texels
uniform float _ScaleX;
uniform float _ScaleY;
uniform float _PerspectiveFilter;
uniform float _Sharpness;

#endif  // KILN_TEXTCORE_PROPERTIES_INCLUDED
