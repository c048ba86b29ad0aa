// The reflection probe of a scene's ambient light, as Unity's built-in pipeline samples one
// (unity_SpecCube0, UNITY_SAMPLE_TEXCUBE_LOD): a cube of the ambient radiance (a sky image,
// Unity's trilight gradient or a flat colour) whose mip m is prefiltered with the GGX lobe of
// the perceptual roughness Unity's perceptualRoughnessToMipmapLevel maps to m, so that
// Unity_GlossyEnvironment reads the split-sum's prefiltered radiance (Karis 2013).
#ifndef KILN_RUNTIME_RENDER_REFLECTION_PROBE_H_
#define KILN_RUNTIME_RENDER_REFLECTION_PROBE_H_

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "kiln/runtime/scene.h"

namespace kiln::runtime {

inline constexpr uint32_t kProbeSize = 64;  // the base mip's face size
inline constexpr uint32_t kProbeMips = 7;   // UNITY_SPECCUBE_LOD_STEPS (6) + 1

struct ReflectionProbe {
    uint32_t size = 0, mips = 0;
    // Per mip, the six faces (+x, -x, +y, -y, +z, -z) of (size >> mip)^2 texels, rows from the
    // top, in Vulkan's cube-face orientation (CubeTexelDirection).
    std::vector<std::vector<glm::vec3>> texels;
};

// The unit direction through face `face` at face coordinates a, b in [-1, 1] (a across, b down),
// the inverse of Vulkan's cube-map face selection (Vulkan 1.1, 15.6.4, table 24).
glm::dvec3 CubeTexelDirection(uint32_t face, double a, double b);

// Unity's mipmapLevelToPerceptualRoughness: the perceptual roughness mip `mip` holds.
double ProbeMipRoughness(uint32_t mip);

// The scene's ambient radiance in direction `d` (unit): the sky image (bilinear), the trilight
// gradient or the flat colour.
glm::dvec3 AmbientRadiance(const Scene& scene, const glm::dvec3& d);

// The probe of the scene's ambient. Mip 0 is the radiance averaged over each texel (a sky's
// texels binned by direction; analytic ambients sampled at texel centres); mip m > 0 is
// sum L(l) D(h) (n . l) / sum D(h) (n . l) with n = v = the texel's direction (GGX D of
// alpha = ProbeMipRoughness(m)^2) over a box-filtered copy of mip 0 fine enough for the lobe
// (mip 1, nearly a mirror, is the 2x2 box of mip 0).
ReflectionProbe MakeReflectionProbe(const Scene& scene);

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_RENDER_REFLECTION_PROBE_H_
