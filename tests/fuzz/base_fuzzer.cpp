// libFuzzer target: the base body of fuzz_bodies.h.
#include "fuzz_bodies.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  meshquilt::fuzz::limit_memory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  meshquilt::fuzz::base_body(data, size);
  return 0;
}
