// kiln test on the passes the forward harness does not draw (kiln/tools/variant_test.h): each is
// drawn by the runtime's own planners on the harness's scene (tool_access::HarnessDrawList), with
// the variant under test forced into the plan's requests of its pass, and every target of the
// frame read back.
//   ShadowCaster   the casters drawn into a spot light's map (a point light's cube with
//                  SHADOWS_CUBE), compared texel by texel with the harness's sphere and plane
//                  traced through the light's projection (harness/shadow_map_check.h)
//   Deferred       the object's G-buffer, lit by the deferred light pass
//                  (harness/pass_test.cpp)
//   light pass     Hidden/Internal-DeferredShading over the G-buffer of a reference shader, with
//                  the shadow its keywords ask for, against the same frame without shadows
//   collector      Hidden/Internal-ScreenSpaceShadows, in a forward frame with a directional
//                  light's shadow (both harness/internal_pass_test.cpp)
#ifndef KILN_TOOLS_HARNESS_PASS_TEST_H_
#define KILN_TOOLS_HARNESS_PASS_TEST_H_

#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "harness/shadow_map_check.h"
#include "harness/variant_harness.h"

namespace kiln::tools {

using runtime::tool_access::TargetValues;

bool Has(const std::vector<std::string>& keywords, const char* word);
// The first target whose name starts with `prefix`.
const TargetValues* Target(const std::vector<TargetValues>& targets, std::string_view prefix);
// The brightest channel of the image: the frame's light.
float ImageMax(const LinearImage& img);

// The harness's shadowed light: above the sphere and a little behind it, so that the sphere's
// top and the plane are lit and its shadow falls on the plane in front of it, where the camera
// sees it. `range` 0: unlimited.
runtime::Light ShadowLight(runtime::LightType type, float range);
// The side of the harness's shadow maps: a texel is about 1/40 of the sphere's radius.
inline constexpr uint32_t kShadowResolution = 256;

// A shader of the loaded packs (pack, shader) whose passes draw the scene around an internal
// shader's pass: Kiln/StandardMetallic where loaded, else the first with a ForwardBase (or
// untagged) pass, a Deferred pass and a ShadowCaster pass.
std::optional<std::pair<uint32_t, uint32_t>> ReferenceShader(const Renderer& renderer);
inline constexpr const char* kNoReference =
    "no shader of the loaded packs has the ForwardBase, Deferred and ShadowCaster passes the "
    "harness draws the scene around it with (load materials.kpack too)";

// One variant's test in a frame of its own.
struct PassTest {
    Harness& h;
    const Case& c;
    std::vector<std::string> keywords = h.Keywords(c);
    std::string properties = "(defaults)";
    LinearImage image;
    std::vector<TargetValues> targets;

    void Fail(std::string check, std::string message, bool with_image = true) {
        h.Fail(c, keywords, properties, std::move(check), std::move(message),
               with_image ? image : LinearImage{});
    }

    // Draws a plan with every target read back; false (and a failure) when it cannot be drawn.
    // Validation messages and non-finite values in any target are failures too.
    template <typename Plan>
    bool Draw(const runtime::FrameSettings& settings, const Plan& plan) {
        const size_t messages = h.renderer.ValidationMessages().size();
        ++h.report.renders;
        Status e;
        if constexpr (std::is_same_v<Plan, runtime::ForwardPlan>) {
            e = runtime::tool_access::DrawForwardPlan(h.renderer, h.color, h.scene, settings,
                                                      h.camera, plan, image, &targets);
        } else {
            e = runtime::tool_access::DrawDeferredPlan(h.renderer, h.color, h.scene, settings,
                                                       h.camera, plan, image, &targets);
        }
        if (!e.ok()) {
            Fail("pipeline", e.error().message, false);
            return false;
        }
        const std::vector<std::string> all = h.renderer.ValidationMessages();
        if (all.size() > messages) {
            Fail("validation", all[messages]);
        }
        for (const TargetValues& t : targets) {
            if (std::string bad = CheckFinite(t.values, t.width, t.channels); !bad.empty()) {
                Fail("finite", "target '" + t.name + "': " + bad);
                return true;
            }
        }
        if (std::string bad = CheckFinite(image.rgba, image.width, 4); !bad.empty()) {
            Fail("finite", bad);
        }
        return true;
    }

    void ShadowCaster();  // harness/pass_test.cpp
    // The object as its shader's first forward pass draws it, seen through a map face's
    // projection (harness/shadow_map_check.h); none without a forward pass.
    std::optional<ShadowReference> ObjectSeenFrom(const glm::mat4& view_projection,
                                                  uint32_t size,
                                                  const MaterialInstance& m,
                                                  const runtime::Light& light,
                                                  bool mirrored);
    void Deferred();
    void CheckNormals(bool octahedral);
    void LightPass();  // harness/internal_pass_test.cpp
    void Collector();
};

}  // namespace kiln::tools

#endif  // KILN_TOOLS_HARNESS_PASS_TEST_H_
