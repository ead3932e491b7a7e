// jemalloc's settings, read as it starts; built into the program only where it links jemalloc.
// Measured on the 8000 x 8000 benchmark's default run, medians of 6 in turns.
//
// An arena per processor, not jemalloc's four per processor: a thread then reuses the memory
// freed on its processor, where it took fresh pages from the kernel while the pages freed into
// other arenas were handed back, each hand-back flushing every processor's address cache: 8 990
// madvise calls became about 3 600, processor time 8.90 -> 7.58 s, wall time 5.23 -> 4.50 s, peak
// memory 297 -> 315 MB (one arena: 7.44 s, 4.39 s, 276 MB here, but all of a larger machine's
// threads would wait on it).
//
// Huge pages asked for (where the system grants them on request, as Debian's does): the run's
// buffers of strokes and chain cells are touched fresh in 2 MB pages, not 4 KB ones; 161 000 page
// faults became 12 000, processor time 7.44 -> 6.08 s, wall time 4.38 -> 3.51 s, peak memory
// 315 -> 340 MB. Where the system gives no huge pages, this asks for nothing.
//
// A user's MALLOC_CONF is read after this, and wins.
extern "C" {
const char* malloc_conf = "percpu_arena:percpu,thp:always";  // the name jemalloc looks up
}
