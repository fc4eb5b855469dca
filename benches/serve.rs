//! `jamchart serve` under load (`cargo bench --bench serve`): a real server process on the
//! loopback and real sockets.
//!
//! 1. 64 keep-alive clients ask 10^5 statics questions between them: errors, p50 and p99
//!    latency, answers per second.
//! 2. The same clients ask a mix: points, ranges, distributions, renders of a small chart.
//! 3. The server's resident memory before, between and after (flat when nothing leaks).
//! 4. One statics answer over HTTP (one client, keep-alive) against spawning `jamchart solve
//!    --format json` for it, as a script calls the tool without a server: medians, and their
//!    ratio (goal: HTTP at most 1/20 of a process).

mod common;

#[path = "../tests/common/http.rs"]
#[allow(dead_code)]
mod http;

use std::process::Command;
use std::time::{Duration, Instant};

use common::median;
use http::{Client, Server};

/// Concurrent clients.
const CLIENTS: usize = 64;

/// Statics questions in the first round.
const STATICS: usize = 100_000;

/// Questions of the mixed round.
const MIXED: usize = 6_400;

fn main() {
    let server = Server::start();
    let pid = server.pid();
    let rss0 = rss_kib(pid);
    let (lat, errors, wall) = round(&server, STATICS, |i| {
        let mu = 0.1 + (i % 1000) as f64 * 4e-4;
        ("POST", "/api/v1/solve".into(), format!("{{\"mu\": {mu}}}"))
    });
    report("statics points", &lat, errors, wall);
    let rss1 = rss_kib(pid);
    let (lat, errors, wall) = round(&server, MIXED, |i| match i % 4 {
        0 => ("POST", "/api/v1/solve".into(), "{\"mu\": 0.3}".into()),
        1 => (
            "POST",
            "/api/v1/solve".into(),
            "{\"mu\": \"0.12:0.3\", \"radius_mm\": 12.5}".into(),
        ),
        2 => (
            "POST",
            "/api/v1/solve".into(),
            "{\"mu\": \"normal(0.21,0.03)\", \"before_mm\": 50}".into(),
        ),
        _ => ("GET", "/api/v1/render/fig6.csv".into(), String::new()),
    });
    report(
        "mix (point, range, distribution, fig6 data)",
        &lat,
        errors,
        wall,
    );
    let rss2 = rss_kib(pid);
    let (_, errors, _) = round(&server, STATICS, |i| {
        let mu = 0.1 + (i % 1000) as f64 * 4e-4;
        ("POST", "/api/v1/solve".into(), format!("{{\"mu\": {mu}}}"))
    });
    let rss3 = rss_kib(pid);
    println!(
        "server RSS: {rss0} KiB at start, {rss1} after 10^5 statics, {rss2} after the mix, {rss3} \
         after 10^5 more statics ({errors} errors)"
    );

    // One client, one question at a time: HTTP against a process per answer, interleaved.
    let mut client = Client::connect(&server);
    let body = b"{\"mu\": 0.3}";
    let mut http_s = Vec::new();
    let mut spawn_s = Vec::new();
    for _ in 0..7 {
        let t0 = Instant::now();
        for _ in 0..200 {
            assert_eq!(client.send("POST", "/api/v1/solve", body).status, 200);
        }
        http_s.push(t0.elapsed().as_secs_f64() / 200.0);
        let t0 = Instant::now();
        for _ in 0..20 {
            let out = Command::new(env!("CARGO_BIN_EXE_jamchart"))
                .args(["solve", "--mu", "0.3", "--format", "json"])
                .output()
                .expect("the binary runs");
            assert!(out.status.success());
        }
        spawn_s.push(t0.elapsed().as_secs_f64() / 20.0);
    }
    let (h, s) = (median(http_s), median(spawn_s));
    println!(
        "one statics answer: HTTP keep-alive {:.1} us, a jamchart solve process {:.0} us: HTTP \
         costs 1/{:.0} of a process (medians of 7 rounds)",
        h * 1e6,
        s * 1e6,
        s / h
    );
}

/// `n` requests from [`CLIENTS`] keep-alive clients, request `i` made by `ask(i)`: each
/// latency in s, the count of responses that were not 200, and the wall time.
fn round(
    server: &Server,
    n: usize,
    ask: impl Fn(usize) -> (&'static str, String, String) + Sync,
) -> (Vec<f64>, usize, Duration) {
    let t0 = Instant::now();
    let per: Vec<(Vec<f64>, usize)> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..CLIENTS)
            .map(|c| {
                let ask = &ask;
                s.spawn(move || {
                    let mut client = Client::connect(server);
                    let mut lat = Vec::new();
                    let mut errors = 0;
                    for i in (c..n).step_by(CLIENTS) {
                        let (method, path, body) = ask(i);
                        let t = Instant::now();
                        let r = client.send(method, &path, body.as_bytes());
                        lat.push(t.elapsed().as_secs_f64());
                        errors += usize::from(r.status != 200);
                    }
                    (lat, errors)
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let wall = t0.elapsed();
    let errors = per.iter().map(|p| p.1).sum();
    let lat = per.into_iter().flat_map(|p| p.0).collect();
    (lat, errors, wall)
}

fn report(what: &str, lat: &[f64], errors: usize, wall: Duration) {
    let mut sorted = lat.to_vec();
    sorted.sort_by(f64::total_cmp);
    let q = |p: f64| sorted[((sorted.len() - 1) as f64 * p).round() as usize] * 1e3;
    println!(
        "{what}: {} requests by {CLIENTS} keep-alive clients, {errors} errors, p50 {:.2} ms, p99 \
         {:.2} ms, {:.0} answers/s",
        lat.len(),
        q(0.5),
        q(0.99),
        lat.len() as f64 / wall.as_secs_f64()
    );
}

/// Resident memory of process `pid`, KiB.
fn rss_kib(pid: u32) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}
