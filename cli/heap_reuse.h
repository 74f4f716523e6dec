#pragma once
//! How the process's heap hands memory back: kept for reuse rather than returned to the system.

namespace meshquilt::cli {

//! Blocks below 32 MiB come from the heap, and freed heap memory stays with the process, so a
//! buffer freed by one patch step is reused by the next instead of being mapped anew (glibc's
//! defaults unmap blocks past its adaptive threshold and trim the heap's top, and the next step
//! faults every page back in; docs/decisions/0021). The peak is what the job allocates at once either way. Call
//! before work starts.
void keep_freed_memory();

}  // namespace meshquilt::cli
