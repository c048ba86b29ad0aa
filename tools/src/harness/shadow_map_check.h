// kiln test's check of a ShadowCaster variant's shadow map (harness/pass_test.h): every texel is
// traced through the light's projection against the harness's scene as it is meant to be (the
// sphere and the plane of harness/harness_scene.h, exactly), and the map must agree.
//   coverage  a texel where the object is holds a depth below the cleared 1, and one where it is
//             not holds 1. Where the object is: where its shader's first forward pass draws it
//             seen through the same projection (the reference: a shader that moves its
//             vertices moves them in its caster too), else where the traced scene is. Texels
//             within eight texels of the reference's outline (or whose rays pass within four
//             depth biases of the scene's) are not judged: the normal bias moves the outline
//             inward by up to one depth bias, two texels; the rest is the tessellation's margin
//   depth     a covered texel's depth, unprojected through the map's view-projection, lands on
//             the surface its ray hits, within five depth biases and 0.02 (the constant and
//             normal biases move it by up to about four on surfaces facing the light within 72
//             degrees, where it is checked, and only where the reference lies on the traced
//             scene): the distance encoding the receivers read back (for a point light,
//             SHADOWS_CUBE's depth along each face's axis)
#ifndef KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_
#define KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

#include "render/tool_access.h"

namespace kiln::tools {

struct ShadowMapCheck {
    std::string coverage, depth;  // what failed, "" when the check passed
    size_t covered = 0, checked = 0;
};

// The object drawn by its first forward pass through a map face's projection, at the map's size:
// its depth (1: nothing drawn) and whether a texel is covered (depth or alpha coverage).
struct ShadowReference {
    std::vector<float> depth;
    std::vector<uint8_t> covered;
};

// `map`: one face of a shadow map (depth, one channel); `view_projection`: the face's;
// `depth_bias`: the light's (runtime::LightShadow), in world units; `reference`: where the object
// is, when its shader has a forward pass to draw it with (else the traced scene says).
ShadowMapCheck CheckShadowMap(const runtime::tool_access::TargetValues& map,
                              const glm::mat4& view_projection,
                              float depth_bias,
                              const ShadowReference* reference);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_
