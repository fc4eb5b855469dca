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
    #[arg(long, value_name = "IP:PORT", default_value = "127.0.0.1:8750", value_parser = address)]
    pub addr: SocketAddr,
}

/// `--addr`: an IP and a port, or `localhost:PORT` (the loopback, 127.0.0.1).
fn address(s: &str) -> std::result::Result<SocketAddr, String> {
    if let Ok(a) = s.parse() {
        return Ok(a);
    }
    match s.strip_prefix("localhost:").map(str::parse::<u16>) {
        Some(Ok(port)) => Ok(SocketAddr::from(([127, 0, 0, 1], port))),
        _ => Err(
            "give IP:PORT, e.g. 127.0.0.1:8750 (this machine only) or 0.0.0.0:8750 (every \
             interface); localhost:PORT is the loopback"
                .into(),
        ),
    }
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

#[cfg(test)]
mod tests {
    /// A user types `localhost:8750` as often as `127.0.0.1:8750`.
    #[test]
    fn an_address_is_an_ip_and_port_or_localhost() {
        assert_eq!(
            super::address("localhost:8751").unwrap().to_string(),
            "127.0.0.1:8751"
        );
        assert_eq!(
            super::address("0.0.0.0:80").unwrap().to_string(),
            "0.0.0.0:80"
        );
        assert_eq!(
            super::address("[::1]:8750").unwrap().to_string(),
            "[::1]:8750"
        );
        let e = super::address("example.com:80").unwrap_err();
        assert!(e.contains("give IP:PORT"), "{e}");
        assert!(super::address("localhost:99999").is_err());
    }
}
