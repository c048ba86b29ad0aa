// kiln test's check of a ShadowCaster variant's shadow map (harness/pass_test.h): every texel is
// traced through the light's projection against the harness's scene as it is meant to be (the
// sphere and the plane of harness/harness_scene.h, exactly), and the map must agree.
//   coverage  a texel whose ray hits the scene holds a depth below the cleared 1, and one whose
//             ray misses it holds 1; texels whose rays pass within a margin of an outline (the
//             sphere's silhouette, the plane's edges) are not judged, the margin being four
//             times the light's depth bias (the normal bias moves the outline inward by up to
//             one; the texel's size and the sphere's tessellation are below one more)
//   depth     a covered texel's depth, unprojected through the map's view-projection, lands on
//             the surface its ray hits, within five depth biases and 0.02 (the constant and
//             normal biases move it by up to about four on surfaces facing the light within 72
//             degrees, where it is checked): the distance encoding the receivers read back
//             (for a point light, SHADOWS_CUBE's depth along each face's axis)
#ifndef KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_
#define KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_

#include <glm/mat4x4.hpp>

#include <string>

#include "render/tool_access.h"

namespace kiln::tools {

struct ShadowMapCheck {
    std::string coverage, depth;  // what failed, "" when the check passed
    size_t covered = 0, checked = 0;
};

// `map`: one face of a shadow map (depth, one channel); `view_projection`: the face's;
// `depth_bias`: the light's (runtime::LightShadow), in world units.
ShadowMapCheck CheckShadowMap(const runtime::tool_access::TargetValues& map,
                              const glm::mat4& view_projection,
                              float depth_bias);

}  // namespace kiln::tools

#endif  // KILN_TOOLS_HARNESS_SHADOW_MAP_CHECK_H_
