//! `jamchart serve`: flags -> [`crate::serve::run`].

use std::net::SocketAddr;

use clap::Args;

use super::threads::Pool;
use crate::error::Result;

/// Flags of `serve`.
#[derive(Debug, Clone, Args)]
pub struct ServeArgs {
    /// Address and port to listen on.
    ///
    /// The loopback (127.0.0.1) by default: only this machine reaches the server. Another
    /// address (0.0.0.0 for every interface) lets anyone who reaches this machine use it, with
    /// no login: put it behind your own proxy for a team. Port 0 picks a free port.
    #[arg(long, value_name = "IP:PORT", default_value = "127.0.0.1:8750")]
    pub addr: SocketAddr,
}

/// Serves until Ctrl-C: the URL on stdout, a warning on stderr when the address is not the
/// loopback.
pub fn run(a: &ServeArgs, pool: Pool) -> Result<()> {
    let limits = crate::serve::Limits::default();
    crate::serve::run(a.addr, limits, pool.shared(), |bound| {
        let url = format!("http://{bound}/");
        if !bound.ip().is_loopback() {
            super::warn(&[format!(
                "listening on {bound}, not the loopback: anyone who can reach this machine on \
                 port {} can use the server (there is no login); give --addr \
                 127.0.0.1:{} to keep it to this machine",
                bound.port(),
                bound.port()
            )]);
        }
        // On stdout, flushed: a script that starts the server reads the port from it.
        use std::io::Write;
        let mut out = std::io::stdout().lock();
        let _ = writeln!(
            out,
            "jamchart: serving the design page at {url} (Ctrl-C stops)"
        );
        let _ = out.flush();
    })
}
