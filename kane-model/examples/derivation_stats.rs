//! Derivation statistics: time, operation counts of M and f after CSE, arena size, peak heap.
//!
//! `cargo run --release -p kane-model --example derivation_stats`

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use kane_model::mechanics::{KaneEquations, Model};
use kane_model::models::{n_link_pendulum, GimbalGyroscope};

/// Counts live and peak heap bytes.
struct PeakAlloc;
static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for PeakAlloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let now = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
        PEAK.fetch_max(now, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: PeakAlloc = PeakAlloc;

fn report(name: &str, build: impl Fn() -> (Model, KaneEquations)) {
    // Time: best of several runs, each building the model from scratch.
    let runs = 5;
    let mut best = f64::INFINITY;
    for _ in 0..runs {
        let t = Instant::now();
        let (m, e) = build();
        best = best.min(t.elapsed().as_secs_f64());
        std::hint::black_box((m.ar.len(), e.forcing.len()));
    }
    LIVE.store(0, Ordering::Relaxed);
    PEAK.store(0, Ordering::Relaxed);
    let (model, eqs) = build();
    let peak = PEAK.load(Ordering::Relaxed);
    let ops = eqs.op_counts(&model.ar);
    let (m_ops, f_ops) = (ops.mass_matrix, ops.forcing);
    println!(
        "| {name} | {:.3} ms | {m_ops} | {f_ops} | {} | {:.1} MiB |",
        best * 1e3,
        model.ar.len(),
        peak as f64 / (1024.0 * 1024.0)
    );
}

fn main() {
    println!("| model | derivation (best of 5) | ops M | ops f | arena nodes | peak heap |");
    println!("|---|---|---|---|---|---|");
    report("gimbal gyroscope", || {
        let mut g = GimbalGyroscope::new().expect("gimbal model");
        let e = g.model.kane().expect("gimbal equations");
        (g.model, e)
    });
    report("gimbal gyroscope, simplified", || {
        let mut g = GimbalGyroscope::new().expect("gimbal model");
        let mut e = g.model.kane().expect("gimbal equations");
        g.model.simplify_equations(&mut e).expect("simplification");
        (g.model, e)
    });
    let sizes: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() { vec![1, 2, 5, 10, 20, 40] } else { sizes };
    for n in sizes {
        report(&format!("n-link pendulum, n = {n}"), || {
            let (mut m, _, _) = n_link_pendulum(n).expect("pendulum model");
            let e = m.kane().expect("pendulum equations");
            (m, e)
        });
    }
}
