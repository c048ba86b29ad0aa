// UsePass: `UsePass "Shader/PASSNAME"` inserts a copy of another shader's pass (its program,
// tags and render state), as Unity does. The named shader is one of the compile, or else a
// .shader file beside the using shader or in an -I folder (read only for its passes), by its name
// or, as Unity finds its built-ins, by the name after "Legacy Shaders/"; the pass is
// the first of that shader whose Name matches, case-insensitively (Unity upper-cases pass names).
#ifndef KILN_DRIVER_USE_PASS_H_
#define KILN_DRIVER_USE_PASS_H_

#include "driver/compile_state.h"

namespace kiln::driver {

// Replaces every UsePass placeholder of st.shaders (FlattenPasses) with the pass it names, or
// reports K3015 and drops it; then names every pass again (pass labels count the SubShader's
// passes).
void ResolveUsePasses(CompileState& st);

// A shader without a ShadowCaster pass casts shadows with the first one along its Fallback chain,
// as in Unity (Legacy Shaders/Diffuse and the other surface shaders without addshadow cast
// through "Legacy Shaders/VertexLit"): that pass is copied into the shader's first SubShader,
// found as UsePass finds shaders. A fallback that cannot be found adds nothing.
void AddFallbackShadowCasters(CompileState& st);

}  // namespace kiln::driver

#endif  // KILN_DRIVER_USE_PASS_H_
