// What kiln test's checks share (kiln/tools/variant_test.h): the variant under test, the
// harness's scene and camera, the material a variant is drawn with, and the report its failures
// and skips go to. The forward passes are tested in harness/variant_test.cpp; the passes other
// paths draw (ShadowCaster, Deferred, the internal light pass and shadow collector) in
// harness/pass_test.cpp.
#ifndef KILN_TOOLS_HARNESS_VARIANT_HARNESS_H_
#define KILN_TOOLS_HARNESS_VARIANT_HARNESS_H_

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "harness/harness_scene.h"
#include "kiln/tools/variant_test.h"

namespace kiln::tools {

struct Case {
    uint32_t pack, shader, pass, variant;
};

// The path that draws a pass's variants, and so how the harness tests them.
enum class PassKind {
    kForward,        // ForwardBase, ForwardAdd, Always or untagged: drawn on the objects
    kShadowCaster,   // into a spot light's map (a point light's cube with SHADOWS_CUBE)
    kDeferred,       // into the G-buffer, lit by the deferred light pass
    kDeferredLight,  // Hidden/Internal-DeferredShading: over a G-buffer the harness draws
    kCollector,      // Hidden/Internal-ScreenSpaceShadows: over the camera's depth
};

// The kind of `pass` of shader `name`; none for a LightMode no path draws (Meta, ...).
std::optional<PassKind> KindOf(const pack::Pack& pk, std::string_view name, uint32_t pass);

// Why no frame of the runtime draws this variant of a kDeferredLight or kCollector pass (a
// shadow keyword of another light type, SHADOWS_SOFT without a shadow, a directional light in
// the ranged lights' pass), or "" when one does.
std::string Unreachable(PassKind kind,
                        std::string_view pass_name,
                        const std::vector<std::string>& keywords);

std::string Describe(float v);
// The brightest channel above `background` in the central eighth of the image (all on the sphere,
// facing a light at the camera).
float CentreMax(const LinearImage& img, float background);
// The first non-finite value of `values` (texels of `width` with `channels` each), as a message;
// "" when every value is finite.
std::string CheckFinite(std::span<const float> values, uint32_t width, uint32_t channels);

struct Harness {
    Renderer& renderer;
    const ColorPipeline& color;
    const VariantTestOptions& options;
    runtime::Scene scene = HarnessScene();
    runtime::CameraSetup camera;
    VariantTestReport report;
    std::vector<std::pair<std::string, size_t>> skips;  // "shader ... pass ...: reason", variants

    runtime::FrameSettings Settings(bool additive) const;
    // The variant's shader at its Properties defaults, with a black main colour drawn white.
    void Material(const Case& c, MaterialInstance& out) const;
    std::vector<std::string> Keywords(const Case& c) const;

    void Fail(const Case& c,
              const std::vector<std::string>& keywords,
              std::string properties,
              std::string check,
              std::string message,
              LinearImage image);
    // Counts the variant as skipped (not tested) with `reason`, once per reason and pass.
    void Skip(const Case& c, const std::string& reason);

    void TestForward(const Case& c);                   // harness/variant_test.cpp
    void TestOtherPass(PassKind kind, const Case& c);  // harness/pass_test.cpp
};

}  // namespace kiln::tools

#endif  // KILN_TOOLS_HARNESS_VARIANT_HARNESS_H_
