//! Real browsers for the gallery's tests (`#[path = "common/browser.rs"] mod browser;`):
//! headless Chromium (Debian's `chromium`, driven by its `--dump-dom` and `--screenshot`
//! switches) and headless Firefox (Debian's `firefox-esr`, driven over WebDriver BiDi, which
//! Firefox speaks natively on `--remote-debugging-port`: no geckodriver, nothing from the
//! network). Each page load is a fresh browser with a fresh profile, so that the page's load
//! event runs its test hooks.
//!
//! Under CI (`CI=true`) a browser that is not installed fails the test; locally it is skipped
//! with the reason printed. `JAMCHART_CHROMIUM` / `JAMCHART_FIREFOX` name other binaries.

use std::io::{BufRead, BufReader, Read};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use base64::Engine;
use serde_json::{Value, json};
use tungstenite::stream::MaybeTlsStream;
use tungstenite::{Message, WebSocket};

/// Which browser.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// Debian's `chromium`.
    Chromium,
    /// Debian's `firefox-esr` (Firefox ESR 140 in Debian 12).
    Firefox,
}

/// An installed browser.
pub struct Browser {
    /// Which one.
    pub kind: Kind,
    /// Its binary.
    pub path: PathBuf,
}

impl Kind {
    fn names(self) -> (&'static str, &'static [&'static str], &'static str) {
        match self {
            Kind::Chromium => (
                "JAMCHART_CHROMIUM",
                &["chromium", "chromium-browser"],
                "chromium",
            ),
            Kind::Firefox => (
                "JAMCHART_FIREFOX",
                &["firefox-esr", "firefox"],
                "firefox-esr",
            ),
        }
    }
}

/// The browser of `kind`, or None (after failing under CI) when it is not installed.
pub fn find(kind: Kind) -> Option<Browser> {
    let (var, names, package) = kind.names();
    let named = std::env::var_os(var).map(PathBuf::from);
    let found = named.or_else(|| {
        names.iter().find_map(|name| {
            std::env::var_os("PATH").and_then(|paths| {
                std::env::split_paths(&paths)
                    .map(|d| d.join(name))
                    .find(|p| p.is_file())
            })
        })
    });
    if found.is_none() {
        let reason = format!("no {package} on PATH (apt-get install {package}, or set {var})");
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI=true and {reason}: the browser test must run in CI"
        );
        super::say_skipped(&reason);
    }
    found.map(|path| Browser { kind, path })
}

impl Browser {
    /// The DOM of `url` once its load event has run, at a window of `size` (w, h) px.
    pub fn dom(&self, url: &str, size: Option<(u32, u32)>) -> String {
        match self.kind {
            Kind::Chromium => {
                let mut args = vec!["--dump-dom".to_string()];
                args.extend(size.map(|(w, h)| format!("--window-size={w},{h}")));
                self.chromium(url, &args)
            }
            Kind::Firefox => {
                let mut ff = Firefox::start(&self.path);
                let context = ff.open(url, size);
                ff.dom(&context)
            }
        }
    }

    /// Saves a PNG screenshot of `url` at a window of `size` (w, h) px to `png`.
    pub fn screenshot(&self, url: &str, size: (u32, u32), png: &Path) {
        let _ = std::fs::remove_file(png);
        match self.kind {
            Kind::Chromium => {
                self.chromium(
                    url,
                    &[
                        format!("--screenshot={}", png.display()),
                        format!("--window-size={},{}", size.0, size.1),
                    ],
                );
            }
            Kind::Firefox => {
                let mut ff = Firefox::start(&self.path);
                let context = ff.open(url, Some(size));
                std::fs::write(png, ff.screenshot(&context)).unwrap();
            }
        }
    }

    /// Firefox only: loads `url` at a window of `size`, taps it with a finger (WebDriver BiDi
    /// touch actions: pointer down and up, the browser makes the click) where the page's `aim`
    /// hook put `data-aim` on the body, and returns the DOM and the value of the script
    /// `probe` after the tap; saves a screenshot to `png`.
    pub fn tap(&self, url: &str, size: (u32, u32), probe: &str, png: &Path) -> (String, Value) {
        assert_eq!(self.kind, Kind::Firefox, "touch is driven over BiDi");
        let mut ff = Firefox::start(&self.path);
        let context = ff.open(url, Some(size));
        let aim = ff.eval(&context, "document.body.getAttribute('data-aim')");
        let (x, y) = aim
            .as_str()
            .and_then(|a| a.split_once(','))
            .map(|(x, y)| (x.parse::<f64>().unwrap(), y.parse::<f64>().unwrap()))
            .unwrap_or_else(|| panic!("no aim hook ran: {aim}"));
        let finger = json!({
            "type": "pointer", "id": "finger", "parameters": { "pointerType": "touch" },
            "actions": [
                { "type": "pointerMove", "x": x.round() as i64, "y": y.round() as i64, "origin": "viewport" },
                { "type": "pointerDown", "button": 0 },
                { "type": "pointerUp", "button": 0 },
            ],
        });
        ff.call(
            "input.performActions",
            json!({ "context": context, "actions": [finger] }),
        );
        let probed = ff.eval(&context, probe);
        std::fs::write(png, ff.screenshot(&context)).unwrap();
        (ff.dom(&context), probed)
    }

    /// Firefox only: a page at `url` in a window of `size`, to drive with scripts.
    pub fn open(&self, url: &str, size: (u32, u32)) -> Page {
        assert_eq!(self.kind, Kind::Firefox, "pages are driven over BiDi");
        let mut ff = Firefox::start(&self.path);
        let context = ff.open(url, Some(size));
        Page { ff, context }
    }

    /// Runs headless chromium on `url` with `args`; panics with its stderr when it fails.
    fn chromium(&self, url: &str, args: &[String]) -> String {
        let profile = tempfile::tempdir().unwrap();
        let out = Command::new(&self.path)
            .args([
                "--headless",
                // Root in a container has no user namespace for the sandbox.
                "--no-sandbox",
                "--disable-gpu",
                "--hide-scrollbars",
                "--no-first-run",
                "--virtual-time-budget=5000",
            ])
            .arg(format!("--user-data-dir={}", profile.path().display()))
            .args(args)
            .arg(url)
            .output()
            .expect("chromium starts");
        assert!(
            out.status.success(),
            "chromium failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    }
}

/// A page open in Firefox, driven by scripts.
pub struct Page {
    ff: Firefox,
    context: String,
}

impl Page {
    /// The value of the script `expression` (a promise is awaited).
    pub fn eval(&mut self, expression: &str) -> Value {
        let r = self.ff.call(
            "script.evaluate",
            json!({ "expression": expression, "target": { "context": self.context },
                    "awaitPromise": true }),
        );
        assert_eq!(r["type"], "success", "{expression}: {r}");
        r["result"]["value"].clone()
    }

    /// Polls `expression` until it is true (a bound on a hung page, not a timing assertion).
    pub fn wait_for(&mut self, expression: &str) {
        for _ in 0..MAX_POLLS {
            if self.eval(expression) == Value::Bool(true) {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        panic!("never true: {expression}\n{}", self.dom());
    }

    /// Loads `url` in the same window and waits for its load event.
    pub fn navigate(&mut self, url: &str) {
        self.ff.call(
            "browsingContext.navigate",
            json!({ "context": self.context, "url": url, "wait": "complete" }),
        );
    }

    /// The DOM as HTML.
    pub fn dom(&mut self) -> String {
        let context = self.context.clone();
        self.ff.dom(&context)
    }

    /// Saves a PNG of the viewport to `png`.
    pub fn screenshot(&mut self, png: &Path) {
        let context = self.context.clone();
        std::fs::write(png, self.ff.screenshot(&context)).unwrap();
    }
}

/// A headless Firefox and its WebDriver BiDi session; killed on drop.
struct Firefox {
    child: Child,
    _profile: tempfile::TempDir,
    ws: WebSocket<MaybeTlsStream<TcpStream>>,
    next_id: u64,
    /// Firefox's stderr after the listening line, collected by a thread (for failures).
    log: std::sync::mpsc::Receiver<String>,
}

impl Drop for Firefox {
    fn drop(&mut self) {
        let _ = self.ws.close(None);
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Most polls (50 ms apart) for the page's hooks to finish: a bound on a hung page, not a
/// timing assertion.
const MAX_POLLS: usize = 400;

impl Firefox {
    /// Starts Firefox on a fresh profile with BiDi on a free port, and opens a session.
    fn start(path: &Path) -> Firefox {
        let profile = tempfile::tempdir().unwrap();
        let mut child = Command::new(path)
            .args(["--headless", "--no-remote", "--remote-debugging-port=0"])
            .arg("--profile")
            .arg(profile.path())
            .arg("about:blank")
            // No crash reporter or update prompts in a test run.
            .env("MOZ_CRASHREPORTER_DISABLE", "1")
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("firefox starts");
        let mut err = BufReader::new(child.stderr.take().unwrap());
        let mut seen = String::new();
        let mut line = String::new();
        let url = loop {
            line.clear();
            if err.read_line(&mut line).unwrap_or(0) == 0 {
                let _ = child.kill();
                panic!("firefox exited before listening for WebDriver BiDi:\n{seen}");
            }
            if let Some(at) = line.find("ws://") {
                break line[at..].trim().to_string();
            }
            seen.push_str(&line);
        };
        // Drain the rest, or Firefox blocks on a full pipe.
        let (tx, log) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut rest = String::new();
            let _ = err.read_to_string(&mut rest);
            let _ = tx.send(rest);
        });
        let (ws, _) = tungstenite::connect(format!("{url}/session")).expect("BiDi connects");
        let mut ff = Firefox {
            child,
            _profile: profile,
            ws,
            next_id: 0,
            log,
        };
        ff.call("session.new", json!({ "capabilities": {} }));
        ff
    }

    /// Sends a BiDi command and returns its result (events in between are skipped).
    fn call(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let msg = json!({ "id": id, "method": method, "params": params });
        self.ws
            .send(Message::text(msg.to_string()))
            .expect("BiDi send");
        loop {
            let m = self.ws.read().unwrap_or_else(|e| {
                let log = self.log.try_recv().unwrap_or_default();
                panic!("BiDi read ({method}): {e}\n{log}")
            });
            let Message::Text(t) = m else { continue };
            let v: Value = serde_json::from_str(t.as_str()).expect("BiDi sends JSON");
            if v["id"] != id {
                continue;
            }
            assert_eq!(v["type"], "success", "BiDi {method} failed: {v}");
            return v["result"].clone();
        }
    }

    /// A script's value in `context`.
    fn eval(&mut self, context: &str, expression: &str) -> Value {
        let r = self.call(
            "script.evaluate",
            json!({ "expression": expression, "target": { "context": context },
                    "awaitPromise": false }),
        );
        assert_eq!(r["type"], "success", "{expression}: {r}");
        r["result"]["value"].clone()
    }

    /// Loads `url` in the first browsing context at a viewport of `size` and waits until its
    /// load event has run (and the gallery's hooks, if any: `data-readoff` on the body);
    /// returns the context.
    fn open(&mut self, url: &str, size: Option<(u32, u32)>) -> String {
        let tree = self.call("browsingContext.getTree", json!({}));
        let context = tree["contexts"][0]["context"]
            .as_str()
            .expect("a browsing context")
            .to_string();
        if let Some((w, h)) = size {
            self.call(
                "browsingContext.setViewport",
                json!({ "context": context, "viewport": { "width": w, "height": h } }),
            );
        }
        self.call(
            "browsingContext.navigate",
            json!({ "context": context, "url": url, "wait": "complete" }),
        );
        let hooks = "document.readyState === 'complete' && (!document.querySelector('figure.readoff') \
                     || document.body.getAttribute('data-readoff') === 'done')";
        let mut polls = 0;
        while self.eval(&context, hooks) != Value::Bool(true) {
            polls += 1;
            assert!(polls < MAX_POLLS, "the page's hooks never finished: {url}");
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        context
    }

    /// The DOM of `context`.
    fn dom(&mut self, context: &str) -> String {
        let dom = self.eval(context, "document.documentElement.outerHTML");
        dom.as_str().unwrap_or_default().to_string()
    }

    /// A PNG of `context`'s viewport.
    fn screenshot(&mut self, context: &str) -> Vec<u8> {
        let r = self.call(
            "browsingContext.captureScreenshot",
            json!({ "context": context }),
        );
        base64::engine::general_purpose::STANDARD
            .decode(r["data"].as_str().expect("screenshot data"))
            .expect("base64 PNG")
    }
}
