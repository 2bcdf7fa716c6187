// The libFuzzer entry point of one target: FUZZ_ENTRY names its harness (fuzz/harness/targets.h).
#include "fuzz/harness/targets.h"

#ifdef FUZZ_HEADER_COUNTS
#include "fuzz/harness/fuzz_util.h"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return impact3d_fuzz::FUZZ_ENTRY(data, size);
}

#ifdef FUZZ_HEADER_COUNTS
// The plot-database targets: one mutation in four writes an extreme value (0, -1, 2^31 - 1,
// 2^31, 2^63 - 1) into a count word of the header (fuzz_util.h), the others are libFuzzer's
// own.  A random byte mutation rarely lands a whole extreme word on a count word.
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  if (seed % 4 == 0 && impact3d_fuzz::write_extreme_header_count(data, size, seed / 4)) return size;
  return LLVMFuzzerMutate(data, size, max_size);
}
#endif
