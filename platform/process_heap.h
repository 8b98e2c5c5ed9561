// How the shadetree process's heap treats memory it frees: kept for the
// next allocation instead of handed back to the system page by page.
//
// glibc returns the free top of each thread's heap to the system once it
// passes 128 KiB (madvise), and maps every block past its mmap threshold
// afresh; both come back as page faults on the next use. A render
// allocates per tile and per step, a compile per module, so the same
// memory was faulted in again and again: a cached stf_holes at 512x512
// spent 0.21-0.27 s of system time in a 0.64-0.71 s render on a KVM host
// whose page faults are slow. Keeping freed memory took it to 0.48-0.51 s
// (docs/architecture.md). For the executable only: a library leaves its
// host's heap to its host.
#pragma once

namespace shadetree {

// Keeps freed memory in the process (up to 1 GiB of free heap top per
// arena) and serves blocks up to 32 MiB from the heap, reused, rather than
// from fresh mappings. Should the C library refuse, nothing changes but
// the speed.
void keep_freed_memory_in_the_process();

}  // namespace shadetree
