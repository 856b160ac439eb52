//! Heap allocations per repetition of the workloads of `bench/workloads.rs` (the cases
//! `examples/bench.rs` times), counted by a global allocator that wraps the system's: how many
//! `alloc`/`realloc` calls one repetition makes, on every thread (the pool's too), and their
//! bytes. Not a timing: the counter costs an atomic add per call.
//!
//! `cargo run --release --example bench_allocs [case ...]` (default `nurbs_trimmed`; `name*`
//! matches the cases starting with `name`). Prints "<case> allocs=<n> reallocs=<n> bytes=<n>".

#[path = "../bench/workloads.rs"]
mod workloads;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// The system allocator, counting.
struct Counting;

static ALLOCS: AtomicU64 = AtomicU64::new(0);
static REALLOCS: AtomicU64 = AtomicU64::new(0);
static BYTES: AtomicU64 = AtomicU64::new(0);

// SAFETY: every call is forwarded unchanged to `System`, which upholds `GlobalAlloc`'s contract;
// the counters are plain atomics.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        BYTES.fetch_add(layout.size() as u64, Relaxed);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Relaxed);
        BYTES.fetch_add(layout.size() as u64, Relaxed);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `System` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        REALLOCS.fetch_add(1, Relaxed);
        BYTES.fetch_add(new_size.saturating_sub(layout.size()) as u64, Relaxed);
        // SAFETY: `ptr` came from `System` with this layout; the caller guarantees `new_size`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn main() {
    let mut filters: Vec<String> = std::env::args().skip(1).collect();
    if filters.is_empty() {
        filters.push("nurbs_trimmed".into());
    }
    let matches = |name: &str, f: &str| f.strip_suffix('*').map_or(name == f, |prefix| name.starts_with(prefix));
    for (name, setup) in workloads::cases() {
        if !filters.iter().any(|f| matches(name, f)) {
            continue;
        }
        let mut w = setup();
        (w.run)();
        let runs = 5;
        let counts = || (ALLOCS.load(Relaxed), REALLOCS.load(Relaxed), BYTES.load(Relaxed));
        let before = counts();
        for _ in 0..runs {
            (w.run)();
        }
        let after = counts();
        let per = |a: u64, b: u64| (b - a) / runs;
        println!(
            "{name} allocs={} reallocs={} bytes={} items={}",
            per(before.0, after.0),
            per(before.1, after.1),
            per(before.2, after.2),
            w.items
        );
    }
}
