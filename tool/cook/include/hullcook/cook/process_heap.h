// The heap of a batch process (a cook, a decompose): kept, and backed by huge pages.
#pragma once

namespace hullcook {

// Tracing and decomposing allocate and free buffers of megabytes. By default glibc maps each
// large one afresh and hands freed memory back, so every buffer pays its page faults again, and
// the first decomposition in a process pays one fault for every 4 KiB it touches (some 3 MB on a
// 10,000-vertex outline: several times the decomposition itself where faults are slow, as in a
// virtual machine). This keeps freed memory in the process for the next buffer and asks for
// transparent huge pages over the first 64 MiB of the heap, so that a fresh heap faults once per
// 2 MiB. Once per process, before the work; a no-op where the C library or kernel lacks it.
void prepare_process_heap();

}  // namespace hullcook
