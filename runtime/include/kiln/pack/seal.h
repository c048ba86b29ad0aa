// Sealing a pack: its per-section sums (SUMS, format 1.4) and its whole-file checksum computed
// over its bytes as they are. The writer seals every pack it builds; tests and fuzzers reseal
// packs they changed on purpose, so that the reader's structural checks are what they reach.
#ifndef KILN_PACK_SEAL_H_
#define KILN_PACK_SEAL_H_

#include <cstdint>
#include <span>

namespace kiln::pack {

// Fills in every SUMS record whose section lies inside the bytes (the table's sum included), then
// the header's checksum. Any bytes are accepted: what cannot be read is left as it is.
void Seal(std::span<uint8_t> bytes);

}  // namespace kiln::pack

#endif  // KILN_PACK_SEAL_H_
