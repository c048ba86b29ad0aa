#include "scene/accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kiln::runtime {

Status ReadAccessor(const tinygltf::Model& m, int index, int want, std::vector<float>& out) {
    if (index < 0 || size_t(index) >= m.accessors.size()) {
        return Error{DiagCode::kBadScene, "accessor " + std::to_string(index) + " does not exist"};
    }
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    if (a.sparse.isSparse) {
        return Error{DiagCode::kBadScene, "sparse accessors are not supported"};
    }
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (comps <= 0 || csize <= 0 || a.bufferView < 0 ||
        size_t(a.bufferView) >= m.bufferViews.size()) {
        return Error{DiagCode::kBadScene,
                     "accessor " + std::to_string(index) + " has no usable buffer view or type"};
    }
    const tinygltf::BufferView& view = m.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size()) {
        return Error{DiagCode::kBadScene,
                     "buffer view " + std::to_string(a.bufferView) + " names no buffer"};
    }
    const std::vector<unsigned char>& data = m.buffers[size_t(view.buffer)].data;
    const size_t elem = size_t(comps) * size_t(csize);
    const size_t stride = view.byteStride ? view.byteStride : elem;
    // Every size from the file is checked without wrapping: the view lies in its buffer, the
    // accessor's offset in its view, and the last element ends in the view. A count near 2^64
    // (whose products wrap) fails here, so count <= the buffer's size bounds the allocation.
    const bool view_fits = view.byteOffset <= data.size() &&
                           view.byteLength <= data.size() - view.byteOffset &&
                           a.byteOffset <= view.byteLength;
    const size_t room = view_fits ? view.byteLength - a.byteOffset : 0;
    const bool fits =
        view_fits &&
        (a.count == 0 ||
         (elem <= room && (a.count - 1) <= (room - elem) / std::max<size_t>(stride, 1)));
    if (!fits) {
        return Error{DiagCode::kBadScene,
                     "accessor " + std::to_string(index) + " reads past its buffer view"};
    }
    const size_t base = view.byteOffset + a.byteOffset;
    out.assign(a.count * size_t(want), 0.0f);
    for (size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = data.data() + base + i * stride;
        for (int c = 0; c < std::min(comps, want); ++c) {
            const unsigned char* q = p + size_t(c) * size_t(csize);
            float v = 0;
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&v, q, 4);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = a.normalized ? float(*q) / 255.0f : float(*q);
                    break;
                case TINYGLTF_COMPONENT_TYPE_BYTE:
                    v = a.normalized ? std::max(float(int8_t(*q)) / 127.0f, -1.0f)
                                     : float(int8_t(*q));
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    uint16_t s;
                    std::memcpy(&s, q, 2);
                    v = a.normalized ? float(s) / 65535.0f : float(s);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    int16_t s;
                    std::memcpy(&s, q, 2);
                    v = a.normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    uint32_t s;
                    std::memcpy(&s, q, 4);
                    v = float(s);
                    break;
                }
                default:
                    return Error{DiagCode::kBadScene, "accessor " + std::to_string(index) +
                                                          " has an unknown component type"};
            }
            out[i * size_t(want) + size_t(c)] = std::isfinite(v) ? v : 0.0f;
        }
    }
    return {};
}

Status ReadIndices(const tinygltf::Model& m, int index, std::vector<uint32_t>& out) {
    std::vector<float> f;
    if (Status read = ReadAccessor(m, index, 1, f); !read.ok()) {
        return read;
    }
    const auto& a = m.accessors[size_t(index)];
    // glTF 2.0, 3.7.2.1: indices are unsigned bytes, shorts or ints (a float index out of range
    // would convert to an integer with undefined behaviour).
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        return Error{DiagCode::kBadScene,
                     "the indices accessor " + std::to_string(index) + " has component type " +
                         std::to_string(a.componentType) +
                         "; glTF indices are unsigned bytes (5121), shorts (5123) or ints (5125)"};
    }
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {  // exact above 2^24
        const auto& view = m.bufferViews[size_t(a.bufferView)];
        const auto& data = m.buffers[size_t(view.buffer)].data;
        const size_t stride = view.byteStride ? view.byteStride : 4;
        out.resize(a.count);
        for (size_t i = 0; i < a.count; ++i) {
            std::memcpy(&out[i], data.data() + view.byteOffset + a.byteOffset + i * stride, 4);
        }
        return {};
    }
    out.assign(f.begin(), f.end());
    return {};
}

}  // namespace kiln::runtime
