//! The Rust side of `bench/compare.sh`: the workloads of `bench/workloads.rs` (the same as
//! `bench/anchor.c` runs on real Mesa and GLU), timed as medians of several runs. Prints
//! "<case> <rate per second>".
//!
//! `cargo run --release --example bench [case ...]` (`name*`: the cases starting with `name`).
//! With `BENCH_COLD=1` each case runs once, untimed warm-up skipped, and prints as
//! `cold_<case>`: the first run of a process, its memory fresh from the kernel (what
//! `bench/compare.sh` runs in new processes for the first `eval_mesh2`). With `BENCH_BEST=1`
//! the fastest run is reported instead of the median: a comparison of two builds on a machine
//! that other work shares.

#[path = "../bench/workloads.rs"]
mod workloads;

use std::time::Instant;

/// The median time of `runs` repetitions, after one untimed warm-up.
fn median_seconds(runs: usize, run: &mut dyn FnMut()) -> f64 {
    run();
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            run();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    // The fastest run where the machine is shared: the other runs measure the other load.
    if std::env::var_os("BENCH_BEST").is_some() {
        return t[0];
    }
    t[t.len() / 2]
}

/// Peak resident memory of the process so far (Linux `VmHWM`), in MiB.
fn peak_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn main() {
    let filters: Vec<String> = std::env::args().skip(1).collect();
    let matches = |name: &str, f: &str| f.strip_suffix('*').map_or(name == f, |prefix| name.starts_with(prefix));
    let wanted = |name: &str| filters.is_empty() || filters.iter().any(|f| matches(name, f));
    let mut cases = workloads::cases();
    // The largest typed case first, so that the process's peak memory is its own.
    cases.sort_by_key(|(name, _)| *name != "grid_4000");
    for (name, setup) in cases {
        if !wanted(name) {
            continue;
        }
        let before = peak_mib();
        let mut w = setup();
        if std::env::var_os("BENCH_COLD").is_some() {
            let start = Instant::now();
            (w.run)();
            println!("cold_{name} {:.0}", w.items / start.elapsed().as_secs_f64());
            continue;
        }
        let override_runs = std::env::var("BENCH_RUNS").ok().and_then(|r| r.parse().ok());
        let runs = if let Some(runs) = override_runs {
            runs
        } else if w.items > 1e7 {
            3
        } else if w.items < 1e5 {
            101
        } else {
            7
        };
        let rate = w.items / median_seconds(runs, &mut w.run);
        println!("{name} {rate:.0}");
        if std::env::var_os("BENCH_VERBOSE").is_some() {
            eprintln!("{name}: {} items per run", w.items);
        }
        if name == "grid_4000" {
            if let (Some(a), Some(b)) = (before, peak_mib()) {
                let mesh = 4001.0 * 4001.0 * (12.0 + 12.0 + 8.0) + 4000.0 * 4000.0 * 24.0;
                eprintln!("grid_4000: peak memory {:.0} MiB for a {:.0} MiB mesh", b - a, mesh / 1048576.0);
            }
        }
    }
}
