//! The `raylab` binary: parses the command line and hands over to the library.

use libmimalloc_sys::{mi_option_get, mi_option_set, mi_option_t};

/// mimalloc, holding on to freed memory for a while: each preview pass allocates and
/// frees frame-sized buffers, and memory handed back to the system comes back page fault
/// by page fault (about 5,000 faults a re-shade pass at 800x600; measured in
/// docs/PERFORMANCE_HISTORY.md).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// `mi_option_purge_delay` in mimalloc 3's `mimalloc.h` (the Rust bindings do not name
/// it), and its default there in milliseconds.
const PURGE_DELAY: mi_option_t = 15;
const PURGE_DELAY_DEFAULT_MS: std::ffi::c_long = 1000;

/// Freed memory goes back to the system after this long unused: after an editing
/// session's pause, not between two passes of the preview.
const KEEP_FREED_MS: std::ffi::c_long = 10_000;

fn main() -> std::process::ExitCode {
    // No transparent huge pages: mimalloc asks for them, and then a first touch of
    // fresh memory may stall on the kernel zeroing (and compacting for) 2 MiB. Moving a
    // light took 74-105 ms with them and 57-64 without; a first colour edit after a
    // re-trace sometimes 30-47 ms instead of 11-13; material edits 8% longer without
    // (docs/PERFORMANCE_HISTORY.md). A kernel that refuses leaves things as they were: harmless.
    // The allocations before `main` (the runtime's first) are covered by mimalloc's
    // `no_thp` feature (Cargo.toml), which stops it asking for huge pages at all: without
    // it each process zeroed two 2 MiB pages before starting, about 1 ms.
    #[cfg(target_os = "linux")]
    let _ = rustix::thread::disable_transparent_huge_pages(true);
    // SAFETY: reading and setting a mimalloc option takes no pointer and may be done at
    // any time; the option is set only where it has purge_delay's documented default,
    // so a renumbered option is left alone.
    unsafe {
        if mi_option_get(PURGE_DELAY) == PURGE_DELAY_DEFAULT_MS {
            mi_option_set(PURGE_DELAY, KEEP_FREED_MS);
        }
    }
    raylab::cli::run()
}
