#include "heap_reuse.h"

#include <malloc.h>

namespace meshquilt::cli {

void keep_freed_memory() {
  // 32 MiB is glibc's largest mmap threshold; a larger block is mapped (and unmapped) as before.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, -1);  // -1: never trim
}

}  // namespace meshquilt::cli
