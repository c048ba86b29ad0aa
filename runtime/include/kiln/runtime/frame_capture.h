// A captured frame (Renderer::Render with a FrameCapture), what the frame debugger shows (kiln
// render --frame-debug DIR), as Unity's Frame Debugger: a frame drawn one step at a time,
// recording for each pass and draw what was drawn (pass, LightMode, shader, variant keywords,
// render state, light, object, mesh with its vertex and index counts, the textures bound and the
// uniform values written, GPU time where the queue has timestamps) and an image of each target
// the pass writes after the step. kiln/tools/frame_debug.h writes it out.
#ifndef KILN_RUNTIME_FRAME_CAPTURE_H_
#define KILN_RUNTIME_FRAME_CAPTURE_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace kiln::runtime {

// A target after a step, as a person can look at it (8-bit RGBA, opaque): light and colour
// targets through the display transform, sRGB colour targets as stored, normals as stored
// (n * 0.5 + 0.5), depth linearised (near white, far dark, nothing black).
struct DebugImage {
    std::string target;  // the frame target's name: "color", "gbuffer2 (normal)", "depth", ...
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;
    // The texels as the target holds them, decoded to what a shader reads (linear light, G-buffer
    // data, stored depth), rows top first, for a readout of a texel's value: a four-channel
    // target's as IEEE half floats (`half`, RGBA), a one-channel target's (depth, a mask) as
    // floats (`single`: 24-bit depth needs them). Empty for thumbnails.
    std::vector<uint16_t> half;
    std::vector<float> single;
    bool depth = false;  // a depth target: `single` holds its stored depth (1: cleared)
};

// A texture a draw bound, by the shader's name for it.
struct DebugTexture {
    std::string name;    // "_MainTex"
    std::string source;  // "file 'x.png'", "glTF image 0 'albedo'", "default 'white'", a target
    uint32_t width = 0, height = 0;
    std::string format;    // "R8G8B8A8_SRGB"; "" when not known
    DebugImage thumbnail;  // at most 64 texels a side; empty where the runtime keeps no copy
};

struct DebugStep {
    std::string pass;  // the frame pass: "forward", "gbuffer", "lighting"
    int draw = -1;     // index of the draw within the pass; -1: the pass's clear or copy
    // A copy step (a GrabPass): "color -> _GrabTexture"; empty otherwise.
    std::string copy;
    // What was drawn (empty for a clear).
    std::string shader, shader_pass, light_mode, keywords, state, light, object;
    std::string mesh;  // "mesh 'sphere', primitive 0", or "the full-screen triangle"
    uint32_t vertex_count = 0, index_count = 0;
    std::vector<DebugTexture> textures;
    // The uniform blocks' members as written, by name (material properties, the object's and
    // the light's values, the frame's globals).
    std::vector<std::pair<std::string, std::vector<float>>> values;
    double gpu_ms = -1;  // timestamp queries around the draw; negative: not supported
    std::vector<DebugImage> images;
};

struct FrameCapture {
    std::string scene;  // for the page's title
    std::string path;   // "forward" or "deferred"
    uint32_t width = 0, height = 0;
    std::vector<DebugStep> steps;
};

}  // namespace kiln::runtime

#endif  // KILN_RUNTIME_FRAME_CAPTURE_H_
