//! The closed form by columns (`models::columns`, what a numpy array of the Python package
//! reaches without Python): 10^6 pushes of mu over [0.05, 1.2] into buffers written before,
//! medians of 21 runs on all threads and on one, in ns a push and the bytes an answer moves
//! at the least (mu read; status, theta_jam, x_jam and the past-palm x_jam written: 33 B).
//!
//! `cargo bench --bench columns`. Where valgrind is installed it also prints the instructions
//! a push takes on one thread: callgrind counts this binary run with `count 1` and `count 3`
//! (one and three maps of 10^6) and the difference is halved, so that the process's start and
//! the buffers' first writes fall out. valgrind's processor has no AVX-512, so the count is
//! that of the AVX2 build of the chunk; the times are of the widest build this processor runs.

mod common;

use std::process::Command;

use common::{instructions, median_s, one_thread_pool};
use jamchart::models::columns::{Answers, Pushes, solve_into};
use jamchart::{ModelSpec, Param, SceneParams};

/// Pushes a map.
const N: usize = 1_000_000;

/// The least bytes an answer moves: mu read, a status byte and three float64 written.
const BYTES: f64 = 8.0 + 1.0 + 3.0 * 8.0;

/// Answers `maps` maps of the [`N`] pushes into the same buffers.
fn maps(maps: usize) -> impl FnMut() {
    // A Weyl sequence over mu's range: every status of the default scene but too_weak.
    let mu: Vec<f64> = (0..N)
        .map(|i| 0.05 + 1.15 * ((i as f64 + 1.0) * 0.618_033_988_75).fract())
        .collect();
    let (mut status, mut theta, mut x, mut past) =
        (vec![0u8; N], vec![0.0; N], vec![0.0; N], vec![0.0; N]);
    move || {
        let pushes = Pushes {
            base: SceneParams::default(),
            columns: vec![(Param::named("mu").expect("a parameter"), &mu[..])],
        };
        for _ in 0..maps {
            let out = Answers {
                status: &mut status,
                theta_jam_deg: &mut theta,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: Some(&mut past),
            };
            solve_into(&ModelSpec::Statics, &pushes, out).expect("valid pushes");
        }
        std::hint::black_box((&status, &theta, &x, &past));
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let [_, word, count] = &args[..]
        && word == "count"
    {
        let count = count.parse().expect("a count of maps");
        one_thread_pool().install(maps(count));
        return;
    }
    let mut run = maps(1);
    run();
    let all = median_s(21, &mut run);
    let one = one_thread_pool().install(|| median_s(21, &mut run));
    let line = |label: &str, s: f64| {
        format!(
            "{label} {:.2} ms ({:.2} ns a push, {:.2} GB/s)",
            s * 1e3,
            s * 1e9 / N as f64,
            BYTES * N as f64 / s / 1e9
        )
    };
    println!(
        "closed form by columns, 10^6 pushes of mu, medians of 21 runs: {}; {}",
        line(&format!("{} threads", rayon::current_num_threads()), all),
        line("1 thread", one)
    );
    let me = std::env::current_exe().expect("this benchmark's path");
    let count = |maps: usize| instructions(Command::new(&me).args(["count", &maps.to_string()]));
    match (count(1), count(3)) {
        (Some(one), Some(three)) => println!(
            "instructions (callgrind, the AVX2 build): {:.1} a push",
            (three - one) / 2.0 / N as f64
        ),
        _ => println!("instructions: valgrind is not installed"),
    }
}
