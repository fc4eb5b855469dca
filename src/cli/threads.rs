//! The worker threads a command runs on: as many as `RAYON_NUM_THREADS` asks (one per core when
//! unset), or the calling thread alone when the system will not start them.
//!
//! rayon's global pool panics on first use when a thread cannot be spawned (`ulimit -u`, an
//! address-space limit too small for the stacks), and a failed global pool cannot be built
//! again. So the threads are started as a local pool first; only if that fails is the global
//! pool made of the calling thread alone, which spawns nothing, once the
//! threads that did start have exited (their stacks freed).

use rayon::{ThreadPool, ThreadPoolBuilder};

use crate::error::{Error, Result};
use crate::limits::MAX_THREADS;

/// The environment variable rayon reads for its thread count.
const THREADS_VAR: &str = "RAYON_NUM_THREADS";

/// 8 MiB, the main thread's stack under Linux's default `ulimit -s`: the command runs on a
/// worker, and must have the stack it had on the main thread (rayon's default is 2 MiB).
const WORKER_STACK_BYTES: usize = 8 << 20;

/// Where a command's parallel work runs.
pub(crate) enum Pool {
    /// Worker threads; the command runs on one of them.
    Threads(ThreadPool),
    /// The calling thread alone (no thread could be started).
    Calling,
}

impl Pool {
    /// The worker threads, shared (None for the calling thread alone: rayon's global pool is
    /// then that thread).
    #[cfg(feature = "serve")]
    pub(crate) fn shared(self) -> Option<std::sync::Arc<ThreadPool>> {
        match self {
            Pool::Threads(pool) => Some(std::sync::Arc::new(pool)),
            Pool::Calling => None,
        }
    }

    /// Runs `op` so that its parallel work uses this pool.
    pub(crate) fn run<R: Send>(&self, op: impl FnOnce() -> R + Send) -> R {
        match self {
            Pool::Threads(pool) => pool.install(op),
            Pool::Calling => op(),
        }
    }
}

/// Starts the threads `RAYON_NUM_THREADS` asks for, or falls back to the calling thread with
/// a warning when they cannot be started; a count that is not a number or above
/// [`MAX_THREADS`] is refused.
pub(crate) fn start() -> Result<Pool> {
    let asked = requested(std::env::var(THREADS_VAR).ok().as_deref())?;
    // The threads are spawned here rather than by rayon so that, when one cannot be, those that
    // did start are joined before the command runs: rayon tells them to stop but does not wait,
    // and their stacks (8 MiB each) held the address space the one-thread run then needed (an
    // address-space limit aborted it in 3 runs of 5).
    let started = std::sync::Mutex::new(Vec::new());
    let threads = ThreadPoolBuilder::new()
        .num_threads(asked)
        .stack_size(WORKER_STACK_BYTES)
        .spawn_handler(|thread| {
            let mut b = std::thread::Builder::new().stack_size(WORKER_STACK_BYTES);
            if let Some(name) = thread.name() {
                b = b.name(name.to_owned());
            }
            let handle = b.spawn(|| thread.run())?;
            started
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .push(handle);
            Ok(())
        })
        .build();
    match threads {
        Ok(pool) => Ok(Pool::Threads(pool)),
        Err(e) => {
            // rayon has told them to stop; each returns once it has seen it.
            for handle in started.into_inner().unwrap_or_else(|e| e.into_inner()) {
                let _ = handle.join();
            }
            let count = match asked {
                0 => "a thread per core".to_string(),
                n => format!("{n} threads"),
            };
            super::warn(&[format!(
                "could not start {count} ({e}); running on one thread"
            )]);
            ThreadPoolBuilder::new()
                .num_threads(1)
                .use_current_thread()
                .build_global()
                .map_err(|e| Error::invalid(THREADS_VAR, 1, format!("one thread: {e}")))?;
            Ok(Pool::Calling)
        }
    }
}

/// The thread count in `RAYON_NUM_THREADS` (`value`), 0 for rayon's default (one per core)
/// when it is unset, empty or 0 (rayon's own reading).
fn requested(value: Option<&str>) -> Result<usize> {
    let Some(text) = value.map(str::trim).filter(|t| !t.is_empty()) else {
        return Ok(0);
    };
    let why = format!("a thread count is 0 (one per core) to {MAX_THREADS}");
    match text.parse::<usize>() {
        Ok(n) if n <= MAX_THREADS => Ok(n),
        _ => Err(Error::invalid(THREADS_VAR, text, why)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thread_counts_are_read_as_rayon_does_within_the_limit() {
        assert_eq!(requested(None).unwrap(), 0);
        assert_eq!(requested(Some(" ")).unwrap(), 0);
        assert_eq!(requested(Some("0")).unwrap(), 0);
        assert_eq!(requested(Some("3")).unwrap(), 3);
        assert_eq!(requested(Some("1024")).unwrap(), MAX_THREADS);
        for bad in ["1025", "100000000", "-1", "two"] {
            let msg = requested(Some(bad)).unwrap_err().to_string();
            assert!(
                msg.contains("RAYON_NUM_THREADS") && msg.contains(bad),
                "{msg}"
            );
        }
    }
}
