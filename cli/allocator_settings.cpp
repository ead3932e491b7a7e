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
// Huge pages are not asked for (jemalloc's thp:always, this file's setting from 2026-12-05 to
// 2026-12-06): the system's own setting decides, as it does for GDAL's tools. On a virtual machine
// that hands free memory back to its host, each fresh 2 MB page is faulted in from the host as it
// is cleared, and that cost more than the 4 KB faults it saved. bench/hillshade_ratio.py 8000,
// two runs each, thp:always / the system's default: defaults 2.25x, 2.35x / 2.11x, 1.99x
// hillshade, 305 / 289 MB; panorama 1.41x, 1.36x / 1.09x, 1.00x gdal_viewshed; exact 0.79x,
// 0.86x / 0.78x, 0.74x. (When it was set, with an arena per processor, it had cut the page
// faults from 161 000 to 12 000; one arena has since cut most of that churn.)
//
// A user's MALLOC_CONF is read after this, and wins.
extern "C" {
const char* malloc_conf = "narenas:1";  // the name jemalloc looks up
}
