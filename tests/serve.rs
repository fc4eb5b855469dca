//! `jamchart serve`: the real server on a free loopback port, asked by a real HTTP client
//! (a socket and HTTP/1.1 written out, so that a test can also send what no client library
//! would: a half-sent request, a broken body) and by real browsers.
//!
//! Each answer is checked against the command line's for the same inputs: the API is a face,
//! and adds nothing of its own.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

use jamchart::ask::{Keywords, SolveQuestion, Words};

use crate::common::browser::{self, Kind};
use crate::common::cli::{SHAFT, jamchart, json_of, stdout, timeless};
use crate::common::http::{Client, Response, Server, read_response};

#[test]
fn the_api_answers_what_the_command_line_answers() {
    let server = Server::start();
    let shaft = r#""radius_mm": 12.5, "mass_kg": 0.4, "force_n": 40, "palm_length_mm": 80"#;
    let shaft_flags = SHAFT;
    let cases: [(&str, String, Vec<&str>); 6] = [
        (
            "solve",
            r#"{"mu": 0.3}"#.into(),
            vec!["solve", "--mu", "0.3"],
        ),
        (
            "solve",
            format!(r#"{{"mu": "0.12:0.3", {shaft}}}"#),
            [&["solve", "--mu", "0.12:0.3"][..], &shaft_flags].concat(),
        ),
        (
            "solve",
            format!(r#"{{"mu": "normal(0.21,0.03)", "before_mm": [50, 60], {shaft}}}"#),
            [
                &["solve", "--mu", "normal(0.21,0.03)", "--before", "50,60"][..],
                &shaft_flags,
            ]
            .concat(),
        ),
        (
            "solve",
            r#"{"mu": 0.3, "model": "all"}"#.into(),
            vec!["solve", "--mu", "0.3", "--model", "all"],
        ),
        (
            "design",
            format!(r#"{{"x_target_mm": 40, "mu": "0.12:0.3", {shaft}}}"#),
            [
                &["design", "--x-target", "40", "--mu", "0.12:0.3"][..],
                &shaft_flags,
            ]
            .concat(),
        ),
        (
            "vlocator",
            r#"{"mu": "0.1:0.25", "load_n": 20, "mass_kg": 0.4}"#.into(),
            vec![
                "vlocator", "--mu", "0.1:0.25", "--load", "20", "--mass", "0.4",
            ],
        ),
    ];
    for (route, body, args) in cases {
        let r = server.post(&format!("/api/v1/{route}"), &body);
        assert_eq!(r.status, 200, "{route} {body}: {}", r.text());
        assert_eq!(r.header("content-type"), Some("application/json"));
        assert_eq!(timeless(r.json()), json_of(&args), "{route} {body}");
        assert!(r.header("jamchart-headline").is_some(), "{route} {body}");
    }
    // The text is the command line's report, settings named by their keys.
    let r = server.post("/api/v1/solve?format=text", r#"{"mu": "0.12:0.3"}"#);
    assert_eq!(r.status, 200);
    let question: SolveQuestion = serde_json::from_str::<Keywords>(r#"{"mu": "0.12:0.3"}"#)
        .map(|k| SolveQuestion::from_keywords(k).unwrap())
        .unwrap();
    assert_eq!(r.text(), question.answer().unwrap().text(Words::Keys));
    // A warning of the library reaches the client in a header.
    let r = server.post("/api/v1/solve", r#"{"mu": 0.3, "samples": 100}"#);
    assert_eq!(r.status, 200);
    let warnings: Vec<String> =
        serde_json::from_str(r.header("jamchart-warnings").expect("a warning")).unwrap();
    assert!(warnings[0].contains("samples"), "{warnings:?}");
}

#[test]
fn a_chart_is_the_render_commands_chart() {
    let server = Server::start();
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(
        dir.path(),
        &[
            "render",
            "universal",
            "--set",
            "radius_mm=12.5",
            "--read-off",
            "mu=0.27",
            "--out",
            "o",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let query = "?radius_mm=12.5&read_off.mu=0.27";
    for ext in ["svg", "png", "json"] {
        let r = server.get(&format!("/api/v1/render/universal.{ext}{query}"));
        assert_eq!(r.status, 200, "{ext}: {}", r.text());
        let file = std::fs::read(dir.path().join(format!("o/universal.{ext}"))).unwrap();
        assert!(r.body == file, "universal.{ext} differs from render's file");
    }
    let view = server
        .get(&format!("/api/v1/render/universal.view{query}"))
        .json();
    assert_eq!(view["kind"], "universal");
    assert!(view["svg"].as_str().unwrap().starts_with("<svg"));
    assert!(view["read_off"]["panels"].is_array());
    // A sweep's data is CSV.
    let r = server.get("/api/v1/render/fig6.csv");
    assert_eq!(r.status, 200, "{}", r.text());
    assert!(r.header("content-type").unwrap().starts_with("text/csv"));
}

#[test]
fn bad_requests_are_refused_by_key_and_reason_never_with_a_server_error() {
    let server = Server::start();
    let refused = |r: &Response, status: u16, key: Option<&str>, reason: &str| {
        assert_eq!(r.status, status, "{}", r.text());
        let e = &r.json()["error"];
        if let Some(key) = key {
            assert_eq!(e["key"], key, "{e}");
        }
        assert!(e["reason"].as_str().unwrap().contains(reason), "{e}");
    };
    let r = server.post("/api/v1/solve", r#"{"mu": 0.3"#);
    refused(&r, 400, Some("body"), "not JSON");
    let r = server.post("/api/v1/solve", r#"{"mu": NaN}"#);
    refused(&r, 400, Some("body"), "not JSON");
    let r = server.post("/api/v1/solve", r#"{"mu": 1e400}"#);
    refused(&r, 400, Some("body"), "not JSON");
    let r = server.post("/api/v1/solve", r#"[1, 2]"#);
    refused(&r, 422, Some("body"), "JSON object");
    // The command line's words for the same mistakes.
    let r = server.post("/api/v1/solve", r#"{"mu": -1}"#);
    refused(&r, 422, Some("mu"), "must be a finite number >= 0");
    let r = server.post("/api/v1/solve", r#"{"raduis_mm": 12}"#);
    refused(&r, 422, Some("raduis_mm"), "did you mean radius_mm?");
    let r = server.post("/api/v1/solve", r#"{"mu": [1, 2]}"#);
    refused(&r, 422, Some("mu"), "give a number");
    let r = server.post("/api/v1/solve", r#"{"mu": null}"#);
    refused(&r, 422, Some("mu"), "leave the key out");
    let r = server.post("/api/v1/solve", r#"{"force_n": 1e308, "mass_kg": 1e-308}"#);
    assert!(r.status < 500, "{}", r.text());
    let r = server.post(
        "/api/v1/solve",
        r#"{"mu": "normal(0.3,0.01)", "model": "min-norm", "samples": 1000000}"#,
    );
    refused(&r, 413, Some("samples"), "the server's limit per request");
    let big = format!(r#"{{"mu": 0.3, "pad": "{}"}}"#, "x".repeat(100_000));
    let r = server.post("/api/v1/solve", &big);
    refused(&r, 413, Some("body"), "at most 64 KiB");
    // No file is ever reached: scenes by built-in name only, no base.
    for path in [
        "/api/v1/render/..%2F..%2Fetc%2Fpasswd.svg",
        "/api/v1/render/%2Fetc%2Fpasswd.svg",
        "/api/v1/render/fig3.toml.svg",
    ] {
        let r = server.get(path);
        refused(&r, 422, Some("scene"), "not a built-in scene");
    }
    let r = server.get("/api/v1/render/fig3.svg?base=/etc/passwd");
    refused(&r, 422, Some("base"), "reads a file");
    let r = server.get("/api/v1/render/fig3.svg?chart.x_axis.count=20000&chart.y_axis.count=20000");
    assert!(matches!(r.status, 413 | 422), "{}", r.text());
    let r = server.get("/api/v1/render/fig3.exe");
    refused(&r, 404, Some("format"), ".svg, .png");
    let r = server.get("/api/v1/solve");
    assert_eq!(r.status, 405, "{}", r.text());
    let r = server.get("/etc/passwd");
    assert_eq!(r.status, 404, "{}", r.text());
    // A page of another site renamed to 127.0.0.1 (DNS rebinding) reads nothing.
    let mut s = TcpStream::connect(server.addr).unwrap();
    s.write_all(
        b"GET /api/v1/settings HTTP/1.1\r\nHost: evil.example:8750\r\nConnection: close\r\n\r\n",
    )
    .unwrap();
    refused(&read_response(&mut s), 421, Some("host"), "loopback");
    // The title is text in the SVG, and the SVG runs no script when opened.
    let r = server.get("/api/v1/render/fig6.svg?title=%3Cscript%3Ealert(1)%3C%2Fscript%3E");
    assert_eq!(r.status, 200, "{}", r.text());
    assert!(!r.text().contains("<script>"), "the title is escaped");
    assert!(
        r.header("content-security-policy")
            .unwrap()
            .contains("default-src 'none'")
    );
}

#[test]
fn a_slow_client_holds_no_worker_and_is_let_go() {
    let server = Server::start();
    // Half a request line, then nothing.
    let mut slow = TcpStream::connect(server.addr).unwrap();
    let host = server.addr;
    slow.write_all(format!("POST /api/v1/solve HTTP/1.1\r\nHost: {host}\r\n").as_bytes())
        .unwrap();
    // A body announced and never sent.
    let mut stalled = TcpStream::connect(server.addr).unwrap();
    stalled
        .write_all(
            format!("POST /api/v1/solve HTTP/1.1\r\nHost: {host}\r\nContent-Length: 100\r\n\r\n{{")
                .as_bytes(),
        )
        .unwrap();
    // Others are answered meanwhile.
    for _ in 0..20 {
        assert_eq!(server.post("/api/v1/solve", r#"{"mu": 0.3}"#).status, 200);
    }
    // The stalled body gets 408 once its time is up; the slow headers get the connection
    // closed.
    stalled
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    let r = read_response(&mut stalled);
    assert_eq!(r.status, 408, "{}", r.text());
    slow.set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    let mut rest = Vec::new();
    let read = slow.read_to_end(&mut rest);
    assert!(
        read.is_ok() || rest.is_empty(),
        "the server let the slow client go: {read:?}"
    );
}

#[test]
fn concurrent_clients_get_the_same_answers() {
    let server = Server::start();
    let want = timeless(server.post("/api/v1/solve", r#"{"mu": 0.25}"#).json());
    std::thread::scope(|s| {
        for t in 0..16 {
            let (server, want) = (&server, &want);
            s.spawn(move || {
                // Half the clients keep their connection open, half open one per request.
                let mut kept = (t % 2 == 0).then(|| Client::connect(server));
                for i in 0..25 {
                    let (method, path, body) = match (t + i) % 5 {
                        0 => ("GET", "/api/v1/render/fig6.csv", ""),
                        _ => ("POST", "/api/v1/solve", r#"{"mu": 0.25}"#),
                    };
                    let r = match &mut kept {
                        Some(c) => c.send(method, path, body.as_bytes()),
                        None => server.send(method, path, body.as_bytes()),
                    };
                    assert_eq!(r.status, 200, "{}", r.text());
                    if (t + i) % 5 != 0 {
                        assert_eq!(&timeless(r.json()), want);
                    }
                }
            });
        }
    });
}

#[test]
fn ctrl_c_lets_the_answer_in_flight_finish_then_exits() {
    let mut server = Server::start();
    let addr = server.addr;
    // A request whose body is half sent when Ctrl-C comes, the rest after it: in flight
    // whatever the machine's load, and answered within the server's grace.
    let in_flight = std::thread::spawn(move || {
        let mut s = TcpStream::connect(addr).unwrap();
        let body = r#"{"mu": 0.3}"#;
        let head = format!(
            "POST /api/v1/solve HTTP/1.1\r\nHost: {addr}\r\nContent-Length: {}\r\n\
             Connection: close\r\n\r\n",
            body.len()
        );
        s.write_all(head.as_bytes()).unwrap();
        s.write_all(&body.as_bytes()[..4]).unwrap();
        std::thread::sleep(Duration::from_millis(400));
        s.write_all(&body.as_bytes()[4..]).unwrap();
        let r = read_response(&mut s);
        (r, Instant::now())
    });
    std::thread::sleep(Duration::from_millis(100));
    let interrupted = Instant::now();
    let (status, took) = server.interrupt();
    let (r, answered) = in_flight.join().unwrap();
    assert_eq!(r.status, 200, "{}", r.text());
    assert!(
        answered > interrupted,
        "the answer came after Ctrl-C: it was in flight"
    );
    assert!(status.success(), "{status:?}");
    // The grace is 1.5 s; generous for a loaded machine.
    assert!(took < Duration::from_secs(10), "{took:?}");
    assert!(
        TcpStream::connect(addr).is_err(),
        "nothing listens after the exit"
    );
}

/// The page, driven by a real Firefox: typing, a bad value, a range, the URL, the chart.
#[test]
fn the_page_answers_as_you_type_in_firefox() {
    let Some(firefox) = browser::find(Kind::Firefox) else {
        return;
    };
    let server = Server::start();
    let mut page = firefox.open(&server.url("/"), (1400, 1300));
    let ready = "document.body.getAttribute('data-state') === 'ready'";
    page.wait_for(ready);
    let typed = |page: &mut browser::Page, key: &str, value: &str| {
        page.eval(&format!(
            "(function () {{ var i = document.querySelector('#form-palm [name={key}]'); \
             i.value = '{value}'; document.body.setAttribute('data-state', 'typing'); \
             i.dispatchEvent(new Event('input', {{ bubbles: true }})); return true; }})()"
        ));
        page.wait_for(ready);
    };
    typed(&mut page, "mu", "0.3");
    let report = page.eval("document.getElementById('report').textContent");
    let cli_text = stdout(&jamchart(
        tempfile::tempdir().unwrap().path(),
        &["solve", "--mu", "0.3"],
    ));
    let line = |text: &str, start: &str| {
        text.lines()
            .find(|l| l.trim_start().starts_with(start))
            .unwrap_or_else(|| panic!("no {start} in {text}"))
            .to_string()
    };
    let report = report.as_str().unwrap();
    assert_eq!(line(report, "theta_jam"), line(&cli_text, "theta_jam"));
    assert_eq!(line(report, "x_jam"), line(&cli_text, "x_jam"));
    // A bad value: the command line's message beside the field.
    typed(&mut page, "mu", "-1");
    let error = page.eval("document.getElementById('form-palm-mu-error').textContent");
    assert!(
        error
            .as_str()
            .unwrap()
            .contains("must be a finite number >= 0"),
        "{error}"
    );
    assert_eq!(
        page.eval("document.querySelector('#form-palm [name=mu]').getAttribute('aria-invalid')"),
        "true"
    );
    // A range: its interval.
    typed(&mut page, "mu", "0.12:0.3");
    let report = page.eval("document.getElementById('report').textContent");
    assert!(
        report
            .as_str()
            .unwrap()
            .contains("theta_jam from 14.020 to 34.206 deg"),
        "{report}"
    );
    // The URL holds the state: loading it again gives the same page.
    let url = page.eval("location.href").as_str().unwrap().to_string();
    assert!(url.contains("mu=0.12%3A0.3"), "{url}");
    page.navigate(&url);
    page.wait_for(ready);
    assert_eq!(
        page.eval("document.querySelector('#form-palm [name=mu]').value"),
        "0.12:0.3"
    );
    // The chart reads off under the pointer what the command line answers: point at
    // (mu 0.3, F/(m g) of the default part) on the universal chart.
    typed(&mut page, "mu", "0.3");
    page.wait_for("!!document.querySelector('#chart img').complete");
    let live = page.eval(
        "(function () {
           var fig = document.getElementById('chart');
           var c = JSON.parse(fig.querySelector('script.readoff-data').textContent);
           var p = c.panels[0], f = p.frame, img = fig.querySelector('img');
           var box = img.getBoundingClientRect();
           var frac = function (a, v) { var t = a.log ? Math.log : function (x) { return x; };
             return (t(v) - t(a.min)) / (t(a.max) - t(a.min)); };
           var ratio = 200 / (1 * 9.806);
           var x = box.left + (f.left + frac(c.x, 0.3) * (f.right - f.left)) * box.width;
           var y = box.top + (f.bottom - frac(p.y, ratio) * (f.bottom - f.top)) * box.height;
           fig.querySelector('.plot').dispatchEvent(new PointerEvent('pointermove',
             { bubbles: true, clientX: x, clientY: y }));
           return fig.querySelector('.live').textContent;
         })()",
    );
    let live = live.as_str().unwrap();
    assert!(
        live.contains("34.2"),
        "the read-off gives theta_jam 34.2 deg: {live}"
    );
    let shot = std::env::temp_dir().join("jamchart-serve-firefox.png");
    page.screenshot(&shot);
    crate::common::say_skipped(&format!("(not a skip) screenshot: {}", shot.display()));
}

/// The page in Chromium: the state of its URL answered as the command line does.
#[test]
fn the_page_answers_its_url_in_chromium() {
    let Some(chromium) = browser::find(Kind::Chromium) else {
        return;
    };
    let server = Server::start();
    let page = |query: &str| chromium.dom(&server.url(query), Some((1400, 1300)));
    let cli = |args: &[&str]| stdout(&jamchart(tempfile::tempdir().unwrap().path(), args));
    let dom = page("/?mu=0.3");
    let cli_text = cli(&["solve", "--mu", "0.3"]);
    let theta = cli_text
        .lines()
        .find(|l| l.trim_start().starts_with("theta_jam"))
        .unwrap()
        .trim();
    assert!(dom.contains(theta), "{theta} not in the page");
    assert!(dom.contains("data-state=\"ready\""), "the page finished");
    let dom = page("/?mu=-1");
    assert!(
        dom.contains("must be a finite number &gt;= 0"),
        "the refusal is shown"
    );
    let dom = page("/?tab=vblock&v.mu=0.1:0.25&v.load_n=20&v.mass_kg=0.4");
    let cli_v = cli(&[
        "vlocator", "--mu", "0.1:0.25", "--load", "20", "--mass", "0.4",
    ]);
    let first = cli_v.lines().find(|l| !l.trim().is_empty()).unwrap().trim();
    let escaped = first
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    assert!(dom.contains(&escaped), "{first} not in the V-block tab");
}
