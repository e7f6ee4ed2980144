//! The `raylab` binary: parses the command line and hands over to the library.

/// mimalloc keeps the memory it gets from the system: each preview pass allocates and
/// frees frame-sized buffers, which the system allocator hands back and then takes again
/// page fault by page fault (measured in docs/BENCHMARKS.md).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> std::process::ExitCode {
    raylab::cli::run()
}
