// render_gltf: the smallest engine-side use of the Kiln runtime. Loads a variant pack and a glTF
// scene, renders one frame headless and writes an sRGB PNG through the default OpenColorIO view.
//
//   render_gltf PACK.kpack SCENE.gltf OUT.png
#include <cstdio>

#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: render_gltf PACK.kpack SCENE.gltf OUT.png\n");
        return 2;
    }
    using namespace kiln::runtime;
    auto check = [](const std::optional<Error>& e) {
        if (e) {
            std::fprintf(stderr, "render_gltf: %s\n", e->message.c_str());
        }
        return !e;
    };

    Scene scene;
    std::vector<std::string> warnings;
    if (!check(LoadGltf(argv[2], scene, warnings))) {
        return 1;
    }
    Renderer renderer;
    if (!check(Renderer::Create(RendererOptions{}, renderer)) ||
        !check(renderer.AddPack(argv[1]))) {
        return 1;
    }
    ColorPipeline color;  // $OCIO when set, else the built-in sRGB display
    if (!check(ColorPipeline::Create(ColorOptions{}, color))) {
        return 1;
    }
    FrameSettings frame;
    frame.width = 640;
    frame.height = 360;
    LinearImage image;
    FrameStats stats;
    if (!check(renderer.Render(scene, frame, color, image, stats))) {
        return 1;
    }
    if (!check(WriteDisplayPng(argv[3], image, color))) {
        return 1;
    }
    std::printf("%s: %u objects, %u base + %u additive passes on %s\n", argv[3], stats.objects,
                stats.base_passes, stats.add_passes, renderer.DeviceName().c_str());
    return 0;
}
