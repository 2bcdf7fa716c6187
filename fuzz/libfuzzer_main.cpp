// The libFuzzer entry point of one target: FUZZ_ENTRY names its harness (fuzz/harness/targets.h).
#include "fuzz/harness/targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return impact3d_fuzz::FUZZ_ENTRY(data, size);
}
