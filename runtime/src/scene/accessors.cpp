#include "scene/accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace kiln::runtime {
namespace {

// `count` elements of `elem` bytes, `stride` apart, from byte `offset` of buffer view `view`:
// where they start, once every size from the file is checked without wrapping (the view lies in
// its buffer, the offset in the view, the last element ends in the view; a count near 2^64 whose
// products wrap fails here, so count <= the buffer's size bounds every allocation).
struct Elements {
    const unsigned char* first = nullptr;
    size_t stride = 0;
};

Status Locate(const tinygltf::Model& m,
              int view_index,
              size_t offset,
              size_t count,
              size_t elem,
              bool strided,
              const std::string& what,
              Elements& out) {
    if (view_index < 0 || size_t(view_index) >= m.bufferViews.size()) {
        return Error{DiagCode::kBadScene, what + " has no usable buffer view"};
    }
    const tinygltf::BufferView& view = m.bufferViews[size_t(view_index)];
    if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size()) {
        return Error{DiagCode::kBadScene,
                     "buffer view " + std::to_string(view_index) + " names no buffer"};
    }
    const std::vector<unsigned char>& data = m.buffers[size_t(view.buffer)].data;
    const size_t stride = strided && view.byteStride ? view.byteStride : elem;
    const bool view_fits = view.byteOffset <= data.size() &&
                           view.byteLength <= data.size() - view.byteOffset &&
                           offset <= view.byteLength;
    const size_t room = view_fits ? view.byteLength - offset : 0;
    const bool fits =
        view_fits && (count == 0 ||
                      (elem <= room && (count - 1) <= (room - elem) / std::max<size_t>(stride, 1)));
    if (!fits) {
        return Error{DiagCode::kBadScene, what + " reads past its buffer view"};
    }
    out.first = data.data() + view.byteOffset + offset;
    out.stride = stride;
    return {};
}

// One component as a number: integers exactly, normalized ones mapped to [0, 1] or [-1, 1].
bool Component(const unsigned char* q, int type, bool normalized, double& v) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, q, 4);
            v = f;
            return true;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            v = normalized ? double(*q) / 255.0 : double(*q);
            return true;
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            v = normalized ? std::max(double(int8_t(*q)) / 127.0, -1.0) : double(int8_t(*q));
            return true;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t s;
            std::memcpy(&s, q, 2);
            v = normalized ? double(s) / 65535.0 : double(s);
            return true;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t s;
            std::memcpy(&s, q, 2);
            v = normalized ? std::max(double(s) / 32767.0, -1.0) : double(s);
            return true;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t s;
            std::memcpy(&s, q, 4);
            v = double(s);
            return true;
        }
        default:
            return false;
    }
}

// Accessor `index` as numbers, `want` per element: the buffer view's elements (zeros when a
// sparse accessor has none), then the sparse substitutions (glTF 2.0, 3.6.2.3).
Status ReadNumbers(const tinygltf::Model& m, int index, int want, std::vector<double>& out) {
    if (index < 0 || size_t(index) >= m.accessors.size()) {
        return Error{DiagCode::kBadScene, "accessor " + std::to_string(index) + " does not exist"};
    }
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const std::string what = "accessor " + std::to_string(index);
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (comps <= 0 || csize <= 0) {
        return Error{DiagCode::kBadScene, what + " has no usable type"};
    }
    const size_t elem = size_t(comps) * size_t(csize);
    auto decode = [&](const Elements& e, size_t i, size_t slot) -> Status {
        const unsigned char* p = e.first + i * e.stride;
        for (int c = 0; c < std::min(comps, want); ++c) {
            double v = 0;
            if (!Component(p + size_t(c) * size_t(csize), a.componentType, a.normalized, v)) {
                return Error{DiagCode::kBadScene, what + " has an unknown component type"};
            }
            out[slot * size_t(want) + size_t(c)] = std::isfinite(v) ? v : 0.0;
        }
        return {};
    };
    Elements base;
    if (!(a.sparse.isSparse && a.bufferView < 0)) {
        if (Status s = Locate(m, a.bufferView, a.byteOffset, a.count, elem, true, what, base);
            !s.ok()) {
            return s;
        }
    } else if (a.count > m.accessors.size() + (size_t(1) << 28)) {
        return Error{DiagCode::kBadScene, what + " is sparse with too many elements"};
    }
    out.assign(a.count * size_t(want), 0.0);
    for (size_t i = 0; base.first && i < a.count; ++i) {
        if (Status s = decode(base, i, i); !s.ok()) {
            return s;
        }
    }
    if (!a.sparse.isSparse) {
        return {};
    }
    const size_t n = size_t(std::max(a.sparse.count, 0));
    const int itype = a.sparse.indices.componentType;
    const int isize = tinygltf::GetComponentSizeInBytes(uint32_t(itype));
    if (a.sparse.count < 1 || n > a.count ||
        (itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         itype != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        return Error{DiagCode::kBadScene,
                     what + " has a sparse count or index type glTF does not allow"};
    }
    Elements indices, values;
    if (Status s =
            Locate(m, a.sparse.indices.bufferView, size_t(std::max(a.sparse.indices.byteOffset, 0)),
                   n, size_t(isize), false, what + "'s sparse indices", indices);
        !s.ok()) {
        return s;
    }
    if (Status s =
            Locate(m, a.sparse.values.bufferView, size_t(std::max(a.sparse.values.byteOffset, 0)),
                   n, elem, false, what + "'s sparse values", values);
        !s.ok()) {
        return s;
    }
    for (size_t k = 0; k < n; ++k) {
        double target = 0;
        Component(indices.first + k * size_t(isize), itype, false, target);
        if (target >= double(a.count)) {
            return Error{DiagCode::kBadScene,
                         what + "'s sparse index " + std::to_string(uint64_t(target)) +
                             " is past its " + std::to_string(a.count) + " elements"};
        }
        if (Status s = decode(values, k, size_t(target)); !s.ok()) {
            return s;
        }
    }
    return {};
}

}  // namespace

Status ReadAccessor(const tinygltf::Model& m, int index, int want, std::vector<float>& out) {
    std::vector<double> numbers;
    if (Status s = ReadNumbers(m, index, want, numbers); !s.ok()) {
        return s;
    }
    out.assign(numbers.begin(), numbers.end());
    return {};
}

Status ReadIndices(const tinygltf::Model& m, int index, std::vector<uint32_t>& out) {
    std::vector<double> numbers;
    if (Status read = ReadNumbers(m, index, 1, numbers); !read.ok()) {
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
    out.resize(numbers.size());
    for (size_t i = 0; i < numbers.size(); ++i) {
        out[i] = uint32_t(numbers[i]);  // integers below 2^32: exact in a double
    }
    return {};
}

}  // namespace kiln::runtime
