#include "scene/gltf_input.h"

#include <tiny_gltf.h>

#include <exception>
#include <filesystem>

#include "kiln/base/bytes.h"
#include "kiln/base/files.h"
#include "kiln/runtime/image.h"
#include "scene/gltf_extensions.h"

namespace kiln::runtime {
namespace {

// The JSON chunk of a .glb, or the whole text of a .gltf; empty when the container is malformed
// (tinygltf then reports it).
std::string_view JsonOf(std::string_view bytes, bool binary) {
    if (!binary)
        return bytes;
    constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
    if (bytes.size() < 20 || bytes.substr(0, 4) != "glTF" ||
        base::LoadLe32(bytes, 16) != kJsonChunk)
        return {};
    const uint32_t length = base::LoadLe32(bytes, 12);
    return length <= bytes.size() - 20 ? bytes.substr(20, length) : std::string_view{};
}

bool FileExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);  // what it is, ReadWholeFile says
}

std::string ExpandFilePath(const std::string& path, void*) {
    return path;  // no ~ or $VAR expansion in uris
}

bool ReadWholeFile(std::vector<unsigned char>* out,
                   std::string* err,
                   const std::string& path,
                   void*) {
    Result<std::string> bytes = base::ReadRegularFile(path, kMaxSceneFileBytes);
    if (!bytes) {
        if (err != nullptr)
            *err += bytes.error().message + "\n";
        return false;
    }
    out->assign(bytes.value().begin(), bytes.value().end());
    return true;
}

// tinygltf's image loader replaced by Kiln's (kiln/runtime/image.h). An image that does not decode
// is left empty (the scene loads; the loader warns and binds the default texture) and its reason
// is kept for that warning.
bool LoadImage(tinygltf::Image* image,
               const int index,
               std::string*,
               std::string*,
               int,
               int,
               const unsigned char* bytes,
               int size,
               void* user) {
    auto* errors = static_cast<std::map<int, std::string>*>(user);
    const std::string name = "image " + std::to_string(index) +
                             (image->name.empty() ? std::string() : " '" + image->name + "'");
    Result<Rgba8Image> decoded = DecodeImageRgba8(
        std::string_view(reinterpret_cast<const char*>(bytes), size_t(std::max(size, 0))), name);
    if (!decoded) {
        (*errors)[index] = decoded.error().message;
        return true;
    }
    image->width = int(decoded.value().width);
    image->height = int(decoded.value().height);
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.value().rgba);
    return true;
}

}  // namespace

std::vector<std::string> MessageLines(const std::string& text) {
    std::vector<std::string> out;
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find('\n', at), text.size());
        if (end > at)
            out.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    return out;
}

size_t JsonDepth(std::string_view json, size_t limit) {
    size_t depth = 0, deepest = 0;
    for (size_t i = 0; i < json.size() && deepest <= limit; ++i) {
        const char c = json[i];
        if (c == '"') {
            for (++i; i < json.size() && json[i] != '"'; ++i)
                i += json[i] == '\\' ? 1 : 0;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

Status LoadGltfModel(const std::string& path,
                     tinygltf::Model& model,
                     std::string& warn,
                     std::map<int, std::string>& image_errors) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Error{DiagCode::kBadScene, path + ": no such file"};
    Result<std::string> bytes = base::ReadRegularFile(path, kMaxSceneFileBytes);
    if (!bytes)
        return Error{DiagCode::kBadScene, bytes.error().message};
    const std::string& data = bytes.value();
    const bool binary = std::filesystem::path(path).extension() == ".glb";
    if (JsonDepth(JsonOf(data, binary), kMaxJsonDepth) > kMaxJsonDepth) {
        return Error{DiagCode::kBadScene, path + ": JSON nested more than " +
                                              std::to_string(kMaxJsonDepth) +
                                              " deep; not a glTF file Kiln reads"};
    }
    if (data.size() > std::numeric_limits<unsigned int>::max())
        return Error{DiagCode::kBadScene, path + ": too large"};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(
        {&FileExists, &ExpandFilePath, &ReadWholeFile, &tinygltf::WriteWholeFile, nullptr});
    loader.SetImageLoader(&LoadImage, &image_errors);
    const std::string dir = std::filesystem::path(path).parent_path().string();
    std::string err;
    const auto* p = reinterpret_cast<const unsigned char*>(data.data());
    const auto n = static_cast<unsigned int>(data.size());
    bool ok = false;
    // tinygltf throws on some malformed files (a std::vector::at past an empty list in a .glb):
    // that is a file Kiln cannot read, never an exception out of the runtime.
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, p, n, dir)
                    : loader.LoadASCIIFromString(&model, &err, &warn, data.data(), n, dir);
    } catch (const std::exception& e) {
        return Error{DiagCode::kBadScene,
                     path + ": not a glTF file Kiln reads (tinygltf failed: " + e.what() + ")"};
    } catch (...) {
        return Error{DiagCode::kBadScene, path + ": not a glTF file Kiln reads (tinygltf failed)"};
    }
    if (!ok) {
        // tinygltf fails on some required extensions (Draco's accessors have no bufferView)
        // before saying why: the extension is the better message.
        if (Status required =
                CheckRequiredExtensions(path, RequiredExtensionsOf(JsonOf(data, binary)));
            !required.ok()) {
            return required;
        }
        std::string why;
        for (const std::string& line : MessageLines(err))
            why += (why.empty() ? "" : "; ") + line;
        return Error{DiagCode::kBadScene,
                     path + ": " + (why.empty() ? std::string("not a glTF file") : why)};
    }
    return CheckRequiredExtensions(path, model.extensionsRequired);
}

}  // namespace kiln::runtime
