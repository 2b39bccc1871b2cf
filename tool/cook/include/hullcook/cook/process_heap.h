// The heap of a batch process (a cook, a decompose): kept, and backed by huge pages.
#pragma once

namespace hullcook {

// Tracing and decomposing allocate and free buffers of megabytes. By default glibc maps each
// large one afresh and hands freed memory back, so that every buffer pays its page faults again.
// This keeps freed memory in the process for the next buffer. Once per process, before the work.
void keep_freed_memory();

// keep_freed_memory, and transparent huge pages over the heap's next 80 MiB. The first
// decomposition in a process pays a fault for every 4 KiB it touches (some 3 MB on a
// 10,000-vertex outline: several times the decomposition itself where faults are slow, as in a
// virtual machine); on huge pages a fresh heap faults once per 2 MiB. Resident memory then grows
// by whole huge pages, so a process that watches it in small steps (the cook's repeated runs)
// keeps to keep_freed_memory, and so does a cook, whose tens of MB of huge pages cost more in
// first faults than they save where the kernel compacts memory for each (cmd_cook.cpp). Once per
// process, before the work; a no-op where the C library or the kernel lacks it.
void prepare_process_heap();

}  // namespace hullcook
