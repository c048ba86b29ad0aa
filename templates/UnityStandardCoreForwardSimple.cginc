// UnityStandardCoreForwardSimple.cginc: Unity's reduced forward Standard path (tangent-space
// lighting per vertex) for low-end targets. Kiln's targets are desktop-class, so the simple
// names are the full path's programs under Unity's simple names: same result, more ALU.
#ifndef UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
#define UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED

#include "UnityStandardCore.cginc"

#define VertexOutputBaseSimple VertexOutputForwardBase
#define VertexOutputForwardAddSimple VertexOutputForwardAdd

VertexOutputBaseSimple vertForwardBaseSimple(VertexInput v) {
    return vertForwardBase(v);
}
half4 fragForwardBaseSimpleInternal(VertexOutputBaseSimple i) {
    return fragForwardBaseInternal(i);
}
half4 fragForwardBaseSimple(VertexOutputBaseSimple i) : SV_Target {
    return fragForwardBaseSimpleInternal(i);
}
VertexOutputForwardAddSimple vertForwardAddSimple(VertexInput v) {
    return vertForwardAdd(v);
}
half4 fragForwardAddSimpleInternal(VertexOutputForwardAddSimple i) {
    return fragForwardAddInternal(i);
}
half4 fragForwardAddSimple(VertexOutputForwardAddSimple i) : SV_Target {
    return fragForwardAddSimpleInternal(i);
}

#endif  // UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
