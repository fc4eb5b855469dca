//! `jamchart serve`: the live design page and the HTTP API, a face over [`crate::ask`].
//!
//! Every answer is the library's: a JSON body or a query string becomes [`crate::ask::Keywords`],
//! the question is built and answered by the library, and the answer's serde form is the
//! response (the command line's `--format json` document, byte for byte). The server adds only
//! what HTTP needs: routes (`serve::api`), the page ([`PAGE`]), and what keeps one machine
//! answering many clients:
//!
//! - **Nothing reaches the file system.** Scenes by built-in name only; a scene's `base` (a
//!   parameter file) is refused ([`crate::ask::RenderQuestion::sealed`]); the questions of
//!   solve, design and vlocator read no file.
//! - **Bounded input.** Bodies above [`BODY_LIMIT`] get 413; headers and bodies must arrive
//!   within [`READ_TIMEOUT`] (a slow client holds a connection task, never a worker).
//! - **Bounded work.** Each question runs on a blocking thread under a
//!   [`crate::limits::Budget`] (a sampled answer's estimated CPU time, a chart's memory), so
//!   what is over it is refused before any work with the estimate (413); at most
//!   [`Limits::slots`] questions run at once, at most [`Limits::queue`] wait for a slot, and a
//!   request that finds the queue full, or waits longer than [`SLOT_WAIT`], gets 503 with
//!   `Retry-After`. An answer not ready within [`Limits::time_limit`] gets 503 (the work
//!   finishes on its slot, so the slots still bound what runs).
//! - **Its own name only.** On the loopback, a request whose `Host` is not the server's
//!   address or `localhost` is refused (421): a web page cannot rename its own site to
//!   127.0.0.1 (DNS rebinding) and read the answers.
//! - **Stateless.** No session, no cache, no file: any HTTP load balancer may spread clients
//!   over several servers.

mod api;

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::server::graceful::GracefulShutdown;
use tokio::sync::Semaphore;

use crate::error::{Error, Result};

/// The largest request body read, bytes: a question is a few hundred.
pub const BODY_LIMIT: usize = 64 * 1024;

/// How long a client may take to send a request's headers, and then its body.
pub const READ_TIMEOUT: Duration = Duration::from_secs(10);

/// How long a request waits for a free slot before it is told to come back (503).
pub const SLOT_WAIT: Duration = Duration::from_secs(5);

/// After Ctrl-C, how long requests in flight have to finish before the server exits.
pub const SHUTDOWN_GRACE: Duration = Duration::from_millis(1500);

/// Most connections open at once; more wait in the kernel's queue until one closes.
const MAX_CONNECTIONS: usize = 1024;

/// What the server allows each request and all of them together.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// Questions answered at once.
    pub slots: usize,
    /// Requests that may wait for a slot; more get 503 at once.
    pub queue: usize,
    /// How long an answer may take, from its start on a slot.
    pub time_limit: Duration,
    /// The budget of each question's work.
    pub budget: crate::limits::Budget,
}

impl Default for Limits {
    /// Two slots per core; a sampled answer estimated at up to 10 s of one core; 256 MiB for
    /// one chart; 60 s for an answer.
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, usize::from);
        Limits {
            slots: 2 * cores,
            queue: 256,
            time_limit: Duration::from_secs(60),
            budget: crate::limits::Budget {
                cpu_s: 10.0,
                memory_bytes: 256 << 20,
                source: " (the server's limit per request)",
            },
        }
    }
}

/// The state every request shares.
pub(crate) struct Shared {
    limits: Limits,
    slots: Arc<Semaphore>,
    waiting: std::sync::atomic::AtomicUsize,
    /// The worker threads answers run their parallel work on (rayon's global pool if None).
    pool: Option<Arc<rayon::ThreadPool>>,
    /// The `Host` headers a request may carry when the server listens on the loopback (None:
    /// any): a page of another site that renames itself to 127.0.0.1 (DNS rebinding) is
    /// refused.
    hosts: Option<Vec<String>>,
}

impl Shared {
    fn new(
        limits: Limits,
        pool: Option<Arc<rayon::ThreadPool>>,
        hosts: Option<Vec<String>>,
    ) -> Self {
        Shared {
            limits,
            slots: Arc::new(Semaphore::new(limits.slots)),
            waiting: Default::default(),
            pool,
            hosts,
        }
    }
}

/// The page, with everything it needs inline: it fetches nothing but the API.
pub const PAGE: &str = include_str!("page.html");

/// Serves on `addr` until Ctrl-C or SIGTERM, the answers' parallel work on `pool` (rayon's
/// global pool if None); `ready` is told the address bound (port 0 picks a free one) before
/// the first request is accepted.
pub fn run(
    addr: SocketAddr,
    limits: Limits,
    pool: Option<Arc<rayon::ThreadPool>>,
    ready: impl FnOnce(SocketAddr),
) -> Result<()> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .thread_name("jamchart-serve")
        // An answer runs on a blocking thread with the stack a command has on the main thread.
        .thread_stack_size(8 << 20)
        .build()
        .map_err(|e| Error::io("start", "the server's runtime", e))?;
    let result = runtime.block_on(serve(addr, limits, pool, ready));
    // Work that outlived its time limit is not waited for: the process ends.
    runtime.shutdown_timeout(Duration::from_millis(100));
    result
}

async fn serve(
    addr: SocketAddr,
    limits: Limits,
    pool: Option<Arc<rayon::ThreadPool>>,
    ready: impl FnOnce(SocketAddr),
) -> Result<()> {
    let listener = tokio::net::TcpListener::bind(addr)
        .await
        .map_err(|e| Error::io("listen on", addr.to_string(), e))?;
    let bound = listener
        .local_addr()
        .map_err(|e| Error::io("listen on", addr.to_string(), e))?;
    let shared = Arc::new(Shared::new(limits, pool, loopback_hosts(bound)));
    let router = api::router(shared);
    let graceful = GracefulShutdown::new();
    let connections = Arc::new(Semaphore::new(MAX_CONNECTIONS));
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(TokioTimer::new())
        .header_read_timeout(READ_TIMEOUT)
        .keep_alive(true);
    ready(bound);
    let stop = stop_signal();
    tokio::pin!(stop);
    loop {
        let permit = tokio::select! {
            p = connections.clone().acquire_owned() => p.expect("the semaphore is never closed"),
            _ = &mut stop => break,
        };
        let (stream, _) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(a) => a,
                // Out of file descriptors, a connection reset before it was accepted: the
                // listener is fine; wait a moment rather than spin.
                Err(_) => {
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            _ = &mut stop => break,
        };
        let _ = stream.set_nodelay(true);
        let service = hyper_util::service::TowerToHyperService::new(router.clone());
        let conn = http.serve_connection(TokioIo::new(stream), service);
        let conn = graceful.watch(conn);
        tokio::spawn(async move {
            let _ = conn.await;
            drop(permit);
        });
    }
    drop(listener);
    // Requests in flight finish (each connection closes after its current response).
    let _ = tokio::time::timeout(SHUTDOWN_GRACE, graceful.shutdown()).await;
    Ok(())
}

/// The names a browser on this machine gives a server bound to loopback address `bound`
/// (`127.0.0.1:8750`, `localhost:8750`); None when it listens beyond the loopback.
fn loopback_hosts(bound: SocketAddr) -> Option<Vec<String>> {
    if !bound.ip().is_loopback() {
        return None;
    }
    let port = bound.port();
    Some(vec![
        bound.to_string(),
        format!("localhost:{port}"),
        format!("127.0.0.1:{port}"),
        format!("[::1]:{port}"),
    ])
}

/// Resolves at Ctrl-C (SIGINT) or SIGTERM.
async fn stop_signal() {
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    tokio::select! {
        _ = tokio::signal::ctrl_c() => {}
        _ = term => {}
    }
}
