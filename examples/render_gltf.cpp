// render_gltf: the smallest engine-side use of the Kiln runtime. Loads a variant pack and a glTF
// scene, renders one frame headless and writes an sRGB PNG through the default OpenColorIO view.
// Every call that can fail returns kiln::Result<T> or kiln::Status (an error with a stable code
// and one sentence); the scene's and the frame's warnings come back as a kiln::DiagnosticList.
//
//   render_gltf PACK.kpack SCENE.gltf OUT.png
#include <cstdio>
#include <utility>

#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"

namespace {

bool Report(const kiln::Error& e) {
    std::fprintf(stderr, "render_gltf: %s [%s]\n", e.message.c_str(),
                 kiln::FormatDiagCode(e.code).c_str());
    return false;
}
bool Check(const kiln::Status& s) {
    return s.ok() || Report(s.error());
}
void PrintWarnings(const kiln::DiagnosticList& warnings) {
    for (const kiln::Diagnostic& w : warnings.all()) {
        std::fprintf(stderr, "%s: warning: %s [%s]\n", w.file.c_str(), w.message.c_str(),
                     kiln::FormatDiagCode(w.code).c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: render_gltf PACK.kpack SCENE.gltf OUT.png\n");
        return 2;
    }
    using namespace kiln::runtime;

    kiln::DiagnosticList warnings;
    kiln::Result<Scene> scene = LoadGltf(argv[2], warnings);
    PrintWarnings(warnings);
    if (!scene) {
        return Report(scene.error()), 1;
    }
    kiln::Result<Renderer> renderer = Renderer::Create(RendererOptions{});
    if (!renderer) {
        return Report(renderer.error()), 1;
    }
    if (!Check(renderer.value().AddPack(argv[1]))) {
        return 1;
    }
    // $OCIO when set, else the built-in sRGB display.
    kiln::Result<ColorPipeline> color = ColorPipeline::Create(ColorOptions{});
    if (!color) {
        return Report(color.error()), 1;
    }
    FrameSettings frame;
    frame.width = 640;
    frame.height = 360;
    LinearImage image;
    FrameStats stats;
    const bool rendered =
        Check(renderer.value().Render(scene.value(), frame, color.value(), image, stats));
    PrintWarnings(stats.warnings);
    if (!rendered || !Check(WriteDisplayPng(argv[3], image, color.value()))) {
        return 1;
    }
    std::printf("%s: %u objects, %u base + %u additive passes on %s\n", argv[3], stats.objects,
                stats.base_passes, stats.add_passes, renderer.value().DeviceName().c_str());
    return 0;
}
