//! Criterion benchmarks of the CPU tessellation paths (`cargo bench`): the workloads of
//! `bench/workloads.rs`, reported as elements (grid points or vertices) per second. The
//! comparison with real Mesa and GLU is `bench/compare.sh`.

#[path = "../bench/workloads.rs"]
mod workloads;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::time::Duration;

fn tessellation(c: &mut Criterion) {
    let mut group = c.benchmark_group("tessellation");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for (name, setup) in workloads::cases() {
        let mut w = setup();
        group.throughput(Throughput::Elements(w.items as u64));
        group.bench_function(name, |b| b.iter(|| (w.run)()));
    }
    group.finish();
}

criterion_group!(benches, tessellation);
criterion_main!(benches);
