// jemalloc's settings, read as it starts; built into the program only where it links jemalloc.
// Measured on the 8000 x 8000 benchmark's default run, in turns.
//
// One arena for every thread. A run is a pipeline: strokes are made on one thread and freed on
// another, and its threads move between processors. With an arena per processor (this file's
// setting until 2026-12-05), memory freed into one arena waited there while the other took fresh
// pages from the kernel, and its unused pages were handed back and faulted in again, zeroed each
// time (the kernel's page clearing was 4-8 % of the run's processor time). One arena, 6 pairs:
// processor time 0.960, wall time 0.947, peak memory 347 -> 306 MB; on 16 000 x 16 000, one pair,
// 19.9 -> 16.1 s and 612 -> 594 MB. (Never handing pages back as well, dirty_decay_ms:-1: 0.986
// over 8 pairs at 8000 and 23 MB more, and 835 MB at 16 000, whose spatial index could not reuse
// what the stream left.) Its size classes each have a lock of their own, and each thread's cache
// takes and gives back objects in batches.
//
// Huge pages asked for (where the system grants them on request, as Debian's does): the run's
// buffers of strokes and chain cells are touched fresh in 2 MB pages, not 4 KB ones; 161 000 page
// faults became 12 000, processor time 7.44 -> 6.08 s, wall time 4.38 -> 3.51 s, peak memory
// 315 -> 340 MB. Where the system gives no huge pages, this asks for nothing.
//
// A user's MALLOC_CONF is read after this, and wins.
extern "C" {
const char* malloc_conf = "narenas:1,thp:always";  // the name jemalloc looks up
}
