#pragma once
//! Large arrays filled as soon as they are allocated have their pages mapped in one call rather
//! than one page fault each: on a virtual machine a fault is dear (docs/decisions/0021).

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshquilt {

//! Maps the whole pages of [data, data + bytes) for writing where the kernel can (Linux 5.14,
//! MADV_POPULATE_WRITE); elsewhere nothing happens and the pages fault in as they are touched.
inline void populate_pages(void* data, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > first) ::madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

//! `values` resized to `count` (from empty), its storage populated first.
template <typename T>
void resize_populated(std::vector<T>& values, std::size_t count) {
  values.reserve(count);
  populate_pages(values.data(), count * sizeof(T));
  values.resize(count);
}

}  // namespace meshquilt
