// UnityInstancing.cginc: Unity's GPU-instancing and stereo macros. Kiln draws one object per
// draw call and renders one eye, so every macro compiles to the non-instanced, mono path: the
// instance ID is still read when INSTANCING_ON (SV_InstanceID, in unity_InstanceID), instanced
// properties are plain uniforms, and the stereo eye index is 0 (docs/unity-compat.md).
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#error "Please include UnityShaderVariables.cginc first."
#endif

#if SHADER_TARGET >= 35
#define UNITY_SUPPORT_INSTANCING
#endif
#define UNITY_SUPPORT_STEREO_INSTANCING
#define UNITY_INSTANCING_SUPPORT_FLEXIBLE_ARRAY_SIZE

#if defined(UNITY_SUPPORT_INSTANCING) && defined(INSTANCING_ON)
#define UNITY_INSTANCING_ENABLED
#endif

#define UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(name) cbuffer name {
#define UNITY_INSTANCING_CBUFFER_SCOPE_END }

#if defined(UNITY_INSTANCING_ENABLED)
static uint unity_InstanceID = 0;
static uint unity_BaseInstanceID = 0;
#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID uint instanceID : SV_InstanceID;
#define UNITY_GET_INSTANCE_ID(input) (input).instanceID
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input) \
    { unity_InstanceID = UNITY_GET_INSTANCE_ID(input) + unity_BaseInstanceID; }
#define UNITY_TRANSFER_INSTANCE_ID(input, output) (output).instanceID = UNITY_GET_INSTANCE_ID(input)
#else
#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_TRANSFER_INSTANCE_ID(input, output)
#endif

#define UNITY_VERTEX_INPUT_INSTANCE_ID DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_SETUP_INSTANCE_ID(input) DEFAULT_UNITY_SETUP_INSTANCE_ID(input)

// Stereo: one eye.
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define DEFAULT_UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define DEFAULT_UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define DEFAULT_UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define DEFAULT_UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
#define UNITY_VERTEX_OUTPUT_STEREO DEFAULT_UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX DEFAULT_UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output) \
    DEFAULT_UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output) \
    DEFAULT_UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output) \
    DEFAULT_UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input) \
    DEFAULT_UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)

// Instanced properties: one value per draw, a plain uniform of the property's name.
#define UNITY_INSTANCING_BUFFER_START(buf) CBUFFER_START(UnityInstancing_##buf)
#define UNITY_INSTANCING_BUFFER_END(arr) CBUFFER_END
#define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
#define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#define UNITY_ACCESS_MERGED_INSTANCED_PROP(arr, var) var
#define UNITY_INSTANCED_ARRAY_SIZE 1
#define UNITY_MAX_INSTANCE_COUNT 1

// The matrices are per draw already.
#define UnityObjectToClipPosInstanced(pos) UnityObjectToClipPos(pos)

#endif  // UNITY_INSTANCING_INCLUDED
