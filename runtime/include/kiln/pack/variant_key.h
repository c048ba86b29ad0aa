// VariantKey: which keyword of each keyword set a variant of a pass was compiled with.
//
// Bit layout (64 bits, little-endian when stored):
//   A pass has keyword sets S0, S1, ... in declaration order. Set Si with n_i keywords owns the
//   bit field [shift_i, shift_i + bits_i), where bits_i = ceil(log2(n_i)) (0 for a one-keyword
//   set) and shift_0 = 0, shift_{i+1} = shift_i + bits_i. The field holds the index of the chosen
//   keyword inside the set; index 0 is the set's first keyword, which is "no keyword" for sets
//   written with `_`. Unused high bits are zero.
//   Example: `multi_compile DIRECTIONAL POINT SPOT` (2 bits) then `shader_feature _ _NORMALMAP`
//   (1 bit): SPOT + _NORMALMAP is 0b1'10 = 6.
// A pass whose sets need more than 64 bits is rejected by the compiler (K4011); the pack stores
// shift and bit count per set so a reader never recomputes the layout.
#ifndef KILN_PACK_VARIANT_KEY_H_
#define KILN_PACK_VARIANT_KEY_H_

#include <cstdint>

namespace kiln::pack {

// Bits needed to store an index below `count` (0 for count <= 1).
constexpr uint32_t BitsForCount(uint64_t count) {
    uint32_t bits = 0;
    while (bits < 64 && (uint64_t{1} << bits) < count) {
        ++bits;
    }
    return bits;
}

class VariantKey {
  public:
    constexpr VariantKey() = default;
    constexpr explicit VariantKey(uint64_t bits) : bits_(bits) {}

    constexpr uint64_t bits() const { return bits_; }

    constexpr uint32_t Get(uint32_t shift, uint32_t width) const {
        if (width == 0) {
            return 0;
        }
        return static_cast<uint32_t>((bits_ >> shift) & Mask(width));
    }
    constexpr void Set(uint32_t shift, uint32_t width, uint32_t index) {
        if (width == 0) {
            return;
        }
        bits_ = (bits_ & ~(Mask(width) << shift)) | ((uint64_t{index} & Mask(width)) << shift);
    }

    friend constexpr bool operator==(VariantKey a, VariantKey b) = default;
    friend constexpr bool operator<(VariantKey a, VariantKey b) { return a.bits_ < b.bits_; }

  private:
    static constexpr uint64_t Mask(uint32_t width) {
        return width >= 64 ? ~uint64_t{0} : (uint64_t{1} << width) - 1;
    }
    uint64_t bits_ = 0;
};

}  // namespace kiln::pack

#endif  // KILN_PACK_VARIANT_KEY_H_
