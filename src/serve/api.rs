//! The routes: HTTP in, a library question, its answer out.
//!
//! | route | question | response |
//! |---|---|---|
//! | `GET /` | | the page ([`super::PAGE`]) |
//! | `POST /api/v1/solve` | [`SolveQuestion`] | `jamchart solve --format json`'s document |
//! | `POST /api/v1/design` | [`DesignQuestion`] | `jamchart design --format json`'s document |
//! | `POST /api/v1/vlocator` | [`VlocatorQuestion`] | `jamchart vlocator --format json`'s document |
//! | `GET /api/v1/render/{scene}.{svg,png,json,csv,view}` | [`RenderQuestion`] | the picture, the data, or both for the page (`view`) |
//! | `GET /api/v1/settings` | | every setting ([`crate::SettingDoc`]) |
//! | `GET /api/v1/scenes` | | the built-in scenes: name, kind, title |
//!
//! A question's body is a JSON object of the Python keywords (`{"mu": "0.12:0.3",
//! "radius_mm": 12.5}`); `?format=text` answers with the command line's report instead, in
//! the keys' words. What the answer could not honour (a key without effect, a value that looks
//! like a unit mistake) is in the `jamchart-warnings` header, a JSON list of strings. A refusal
//! is `{"error": {"key", "value", "reason", "fault"}}`: 400 for a body that is not JSON, 422
//! for a question the library refuses, 413 for work over the server's budget, 503 with
//! `Retry-After` when every slot is taken.

use std::sync::Arc;
use std::sync::atomic::Ordering;

use axum::Router;
use axum::body::{Body, Bytes};
use axum::extract::{Path, Query, Request, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use serde::Serialize;

use super::{BODY_LIMIT, READ_TIMEOUT, SLOT_WAIT, Shared};
use crate::ask::{
    DesignQuestion, Keywords, RenderQuestion, SolveQuestion, VlocatorQuestion, Words,
};
use crate::charts::Formats;
use crate::charts::overrides::Setting;
use crate::error::{Error, Fault, Refusal};

/// The routes over `shared`.
pub(super) fn router(shared: Arc<Shared>) -> Router {
    Router::new()
        .route("/", get(page))
        .route("/gallery.js", get(gallery_js))
        .route("/api/v1/solve", post(ask::<SolveQuestion>))
        .route("/api/v1/design", post(ask::<DesignQuestion>))
        .route("/api/v1/vlocator", post(ask::<VlocatorQuestion>))
        .route("/api/v1/render/{file}", get(render))
        .route("/api/v1/settings", get(settings))
        .route("/api/v1/scenes", get(scenes))
        .fallback(not_found)
        .method_not_allowed_fallback(wrong_method)
        .layer(axum::middleware::from_fn_with_state(
            shared.clone(),
            own_host,
        ))
        .with_state(shared)
}

/// Refuses a request addressed to another host than the server's (see [`super::Shared`]).
async fn own_host(
    State(shared): State<Arc<Shared>>,
    request: Request,
    next: axum::middleware::Next,
) -> Response {
    let Some(hosts) = &shared.hosts else {
        return next.run(request).await;
    };
    let host = request
        .headers()
        .get(header::HOST)
        .and_then(|h| h.to_str().ok())
        .unwrap_or_default();
    match hosts.iter().any(|h| h.eq_ignore_ascii_case(host)) {
        true => next.run(request).await,
        false => http_refusal(
            StatusCode::MISDIRECTED_REQUEST,
            Some("host"),
            format!(
                "this server answers requests to {} only (it listens on the loopback)",
                hosts.join(" or ")
            ),
        ),
    }
}

/// A refusal as its response: `{"error": {...}}` with `status`.
fn refused(status: StatusCode, refusal: Refusal) -> Response {
    #[derive(Serialize)]
    struct Body {
        error: Refusal,
    }
    let mut r = json_response(&Body { error: refusal });
    *r.status_mut() = status;
    r
}

/// A refusal of the HTTP request itself (not of a library question): 400, 404, 405, 413,
/// 503.
fn http_refusal(status: StatusCode, key: Option<&str>, reason: impl Into<String>) -> Response {
    let fault = match status {
        StatusCode::SERVICE_UNAVAILABLE => Fault::Cost,
        _ => Fault::Input,
    };
    refused(
        status,
        Refusal {
            key: key.map(str::to_string),
            value: None,
            reason: reason.into(),
            fault,
        },
    )
}

/// The library's refusal of a question, with the status its fault gives.
fn library_refusal(e: &Error) -> Response {
    let status = match e.fault() {
        Fault::Input => StatusCode::UNPROCESSABLE_ENTITY,
        Fault::Cost => StatusCode::PAYLOAD_TOO_LARGE,
        Fault::Io | Fault::Internal => StatusCode::INTERNAL_SERVER_ERROR,
        Fault::Stopped => StatusCode::REQUEST_TIMEOUT,
    };
    refused(status, e.refusal())
}

/// 503 with `Retry-After`: the server is busy, not the question wrong.
fn busy(reason: String) -> Response {
    let mut r = http_refusal(StatusCode::SERVICE_UNAVAILABLE, None, reason);
    r.headers_mut()
        .insert(header::RETRY_AFTER, HeaderValue::from_static("1"));
    r
}

/// `value` as pretty JSON and a newline, as the command line prints it.
fn json_response(value: &impl Serialize) -> Response {
    let text = serde_json::to_string_pretty(value).expect("answers serialise") + "\n";
    ([(header::CONTENT_TYPE, "application/json")], text).into_response()
}

/// Runs `f` on a blocking thread under the server's budget, once a slot is free; the
/// response of a refusal, a busy server or an answer past the time limit otherwise.
async fn work<T: Send + 'static>(
    shared: &Arc<Shared>,
    f: impl FnOnce() -> crate::Result<T> + Send + 'static,
) -> Result<T, Response> {
    struct Waiting<'a>(&'a std::sync::atomic::AtomicUsize);
    impl Drop for Waiting<'_> {
        fn drop(&mut self) {
            self.0.fetch_sub(1, Ordering::Relaxed);
        }
    }
    let limits = shared.limits;
    let permit = match shared.slots.clone().try_acquire_owned() {
        Ok(p) => p,
        Err(_) => {
            let waiting = Waiting(&shared.waiting);
            if waiting.0.fetch_add(1, Ordering::Relaxed) >= limits.queue {
                return Err(busy(format!(
                    "the server is answering {} questions and {} more wait: try again in a \
                     moment",
                    limits.slots, limits.queue
                )));
            }
            match tokio::time::timeout(SLOT_WAIT, shared.slots.clone().acquire_owned()).await {
                Ok(p) => p.expect("the semaphore is never closed"),
                Err(_) => {
                    return Err(busy(format!(
                        "no slot was free within {} s: try again in a moment",
                        SLOT_WAIT.as_secs()
                    )));
                }
            }
        }
    };
    let budget = limits.budget;
    let pool = shared.pool.clone();
    let job = tokio::task::spawn_blocking(move || {
        let _slot = permit;
        let f = move || crate::limits::within(budget, f);
        match pool {
            Some(pool) => pool.install(f),
            None => f(),
        }
    });
    match tokio::time::timeout(limits.time_limit, job).await {
        Ok(Ok(Ok(answer))) => Ok(answer),
        Ok(Ok(Err(e))) => Err(library_refusal(&e)),
        Ok(Err(_panicked)) => Err(library_refusal(&Error::Defect(
            "the answer failed unexpectedly".into(),
        ))),
        Err(_) => Err(busy(format!(
            "the answer took longer than {} s: ask for less (fewer samples, a coarser grid)",
            limits.time_limit.as_secs()
        ))),
    }
}

/// A question the API answers: built from keywords, answered, shown as JSON or text.
trait Question: Sized + Send + 'static {
    type Answer: Serialize + Send + 'static;
    fn from_keywords(keywords: Keywords) -> crate::Result<Self>;
    fn warnings(&self) -> Vec<String>;
    fn answer(&self) -> crate::Result<Self::Answer>;
    fn text(answer: &Self::Answer) -> String;
    fn headline(answer: &Self::Answer) -> String;
}

/// [`Question`] for a library question whose answer has `text` and `headline`; `warnings`
/// gives its warnings in the keys' words.
macro_rules! question {
    ($q:ty, $a:ty, $warnings:expr) => {
        impl Question for $q {
            type Answer = $a;
            fn from_keywords(keywords: Keywords) -> crate::Result<Self> {
                <$q>::from_keywords(keywords)
            }
            fn warnings(&self) -> Vec<String> {
                $warnings(self)
            }
            fn answer(&self) -> crate::Result<$a> {
                <$q>::answer(self)
            }
            fn text(answer: &$a) -> String {
                answer.text(Words::Keys)
            }
            fn headline(answer: &$a) -> String {
                answer.headline()
            }
        }
    };
}

question!(
    SolveQuestion,
    crate::ask::SolveAnswer,
    |q: &SolveQuestion| q.warnings(Words::Keys)
);
question!(
    DesignQuestion,
    crate::ask::DesignAnswer,
    DesignQuestion::warnings
);
question!(
    VlocatorQuestion,
    crate::ask::VlocatorAnswer,
    VlocatorQuestion::warnings
);

/// `?format=json` (the default) or `?format=text`.
#[derive(serde::Deserialize)]
struct FormatQuery {
    format: Option<String>,
}

/// `POST /api/v1/{solve,design,vlocator}`.
async fn ask<Q: Question>(
    State(shared): State<Arc<Shared>>,
    query: Result<Query<FormatQuery>, axum::extract::rejection::QueryRejection>,
    request: Request,
) -> Response {
    let text = match query.map(|q| q.0.format) {
        Ok(None) => false,
        Ok(Some(f)) if f == "json" => false,
        Ok(Some(f)) if f == "text" => true,
        _ => {
            return http_refusal(
                StatusCode::BAD_REQUEST,
                Some("format"),
                "format is json (the default) or text",
            );
        }
    };
    let keywords = match body_keywords(request).await {
        Ok(k) => k,
        Err(r) => return r,
    };
    let result = work(&shared, move || {
        let question = Q::from_keywords(keywords)?;
        let warnings = question.warnings();
        let answer = question.answer()?;
        let shown = match text {
            true => Q::text(&answer),
            false => serde_json::to_string_pretty(&answer).expect("answers serialise") + "\n",
        };
        Ok((shown, warnings, Q::headline(&answer)))
    })
    .await;
    match result {
        Ok((shown, warnings, headline)) => {
            let kind = match text {
                true => "text/plain; charset=utf-8",
                false => "application/json",
            };
            let mut r = ([(header::CONTENT_TYPE, kind)], shown).into_response();
            add_warnings(r.headers_mut(), &warnings);
            if let Ok(v) = HeaderValue::from_str(&ascii_json(&headline)) {
                r.headers_mut().insert("jamchart-headline", v);
            }
            r
        }
        Err(r) => r,
    }
}

/// The `jamchart-warnings` header: the warnings as a JSON list, every character beyond ASCII
/// escaped (a header holds visible ASCII).
fn add_warnings(headers: &mut HeaderMap, warnings: &[String]) {
    if warnings.is_empty() {
        return;
    }
    if let Ok(v) = HeaderValue::from_str(&ascii_json(warnings)) {
        headers.insert("jamchart-warnings", v);
    }
}

/// `value` as JSON in visible ASCII (every other character escaped), for a header.
fn ascii_json(value: &(impl Serialize + ?Sized)) -> String {
    let json = serde_json::to_string(value).expect("strings serialise");
    let mut ascii = String::with_capacity(json.len());
    for c in json.chars() {
        match c {
            ' '..='~' => ascii.push(c),
            c => {
                let mut units = [0u16; 2];
                for u in c.encode_utf16(&mut units) {
                    ascii.push_str(&format!("\\u{u:04x}"));
                }
            }
        }
    }
    ascii
}

/// The body of `request` as keywords: at most [`BODY_LIMIT`] bytes within [`READ_TIMEOUT`],
/// a JSON object.
async fn body_keywords(request: Request) -> Result<Keywords, Response> {
    let too_large = || {
        http_refusal(
            StatusCode::PAYLOAD_TOO_LARGE,
            Some("body"),
            format!("a question's body is at most {} KiB", BODY_LIMIT / 1024),
        )
    };
    let declared = request
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > BODY_LIMIT as u64) {
        return Err(too_large());
    }
    let read = axum::body::to_bytes(request.into_body(), BODY_LIMIT);
    let bytes: Bytes = match tokio::time::timeout(READ_TIMEOUT, read).await {
        Ok(Ok(b)) => b,
        Ok(Err(_)) => return Err(too_large()),
        Err(_) => {
            return Err(http_refusal(
                StatusCode::REQUEST_TIMEOUT,
                Some("body"),
                format!(
                    "the body did not arrive within {} s",
                    READ_TIMEOUT.as_secs()
                ),
            ));
        }
    };
    let bytes: &[u8] = if bytes.iter().all(u8::is_ascii_whitespace) {
        b"{}"
    } else {
        &bytes
    };
    let json: serde_json::Value = serde_json::from_slice(bytes).map_err(|e| {
        http_refusal(
            StatusCode::BAD_REQUEST,
            Some("body"),
            format!("the body is not JSON: {e}"),
        )
    })?;
    Keywords::from_json(json).map_err(|e| library_refusal(&e))
}

/// `GET /api/v1/render/{scene}.{ext}?KEY=VALUE&read_off.PARAM=VALUE`: a built-in scene, its
/// settings replaced by the query's keys (as `render --set KEY=VALUE`, the value read as
/// there) and read off at `read_off.PARAM`.
async fn render(
    State(shared): State<Arc<Shared>>,
    Path(file): Path<String>,
    query: Result<Query<Vec<(String, String)>>, axum::extract::rejection::QueryRejection>,
) -> Response {
    let Some((scene, ext)) = file.rsplit_once('.') else {
        return http_refusal(
            StatusCode::NOT_FOUND,
            Some("scene"),
            "give the scene and a format: /api/v1/render/SCENE.{svg,png,json,csv,view}",
        );
    };
    let formats = match ext {
        "svg" | "view" | "json" | "csv" => Formats::Svg,
        "png" => Formats::Png,
        _ => {
            return http_refusal(
                StatusCode::NOT_FOUND,
                Some("format"),
                "a chart is .svg, .png, .json or .csv (its data), or .view (the page's)",
            );
        }
    };
    let Ok(Query(pairs)) = query else {
        return http_refusal(
            StatusCode::BAD_REQUEST,
            None,
            "the query string does not parse",
        );
    };
    let keywords = match query_keywords(pairs) {
        Ok(k) => k,
        Err(e) => return library_refusal(&e),
    };
    let scene = scene.to_string();
    let ext = ext.to_string();
    let answer = work(&shared, move || {
        let question = RenderQuestion::builtin(&scene, keywords)?;
        question.sealed()?;
        question.answer(formats, Words::Keys)
    })
    .await;
    let answer = match answer {
        Ok(a) => a,
        Err(r) => return r,
    };
    let rendered = &answer.rendered;
    let mut response = match ext.as_str() {
        "svg" => svg_response(rendered.svg.clone().unwrap_or_default()),
        "png" => (
            [(header::CONTENT_TYPE, "image/png")],
            rendered.png.clone().unwrap_or_default(),
        )
            .into_response(),
        "view" => {
            #[derive(Serialize)]
            struct View<'a> {
                name: &'a str,
                kind: &'a str,
                svg: std::borrow::Cow<'a, str>,
                read_off: Option<serde_json::Value>,
                data_format: &'a str,
                warnings: &'a [String],
            }
            let read_off = rendered
                .read_off
                .as_deref()
                .and_then(|r| serde_json::from_str(r).ok());
            json_response(&View {
                name: &rendered.name,
                kind: &answer.kind,
                svg: String::from_utf8_lossy(rendered.svg.as_deref().unwrap_or_default()),
                read_off,
                data_format: rendered.data.extension,
                warnings: &answer.warnings,
            })
        }
        data if data == rendered.data.extension => {
            let kind = match data {
                "json" => "application/json",
                _ => "text/csv; charset=utf-8",
            };
            (
                [(header::CONTENT_TYPE, kind)],
                Body::from(rendered.data.bytes.clone()),
            )
                .into_response()
        }
        other => http_refusal(
            StatusCode::NOT_FOUND,
            Some("format"),
            format!(
                "{}'s data is .{}, not .{other}",
                rendered.name, rendered.data.extension
            ),
        ),
    };
    add_warnings(response.headers_mut(), &answer.warnings);
    response
}

/// An SVG response that runs nothing in a browser that opens it.
fn svg_response(svg: Vec<u8>) -> Response {
    (
        [
            (header::CONTENT_TYPE, "image/svg+xml"),
            (
                header::CONTENT_SECURITY_POLICY,
                "default-src 'none'; style-src 'unsafe-inline'; font-src data:",
            ),
        ],
        svg,
    )
        .into_response()
}

/// A render's query pairs as keywords: each value read as `--set KEY=VALUE` reads it
/// (`0.3` a number, `log` a name, `"0.12:0.3"` a range), `read_off.PARAM` into the
/// `read_off` table. A key given twice is refused.
fn query_keywords(pairs: Vec<(String, String)>) -> crate::Result<Keywords> {
    let mut keywords = Keywords::default();
    let mut read_off = toml::Table::new();
    for (key, raw) in pairs {
        let setting: Setting = format!("{key}={raw}")
            .parse()
            .map_err(|reason: String| Error::invalid(&key, &raw, reason))?;
        let (table, key) = match key.strip_prefix("read_off.") {
            Some(param) => (&mut read_off, param.to_string()),
            None => (&mut keywords.0, key),
        };
        if table.insert(key.clone(), setting.value).is_some() {
            return Err(Error::invalid(
                &key,
                &raw,
                "given twice: give each key once",
            ));
        }
    }
    if !read_off.is_empty() {
        keywords
            .0
            .insert("read_off".into(), toml::Value::Table(read_off));
    }
    Ok(keywords)
}

/// `GET /api/v1/settings`: every setting, as `jamchart settings` lists them.
async fn settings() -> Response {
    json_response(&crate::settings::documented())
}

/// `GET /api/v1/scenes`: the built-in scenes, as `jamchart scenes` lists them (read once:
/// they are built into the binary).
async fn scenes() -> Response {
    #[derive(Serialize)]
    struct SceneDoc {
        name: String,
        kind: String,
        title: String,
    }
    static DOCS: std::sync::OnceLock<Vec<SceneDoc>> = std::sync::OnceLock::new();
    let docs = DOCS.get_or_init(|| {
        crate::charts::builtin_scene_names()
            .into_iter()
            .filter_map(|name| {
                let scene = crate::charts::SceneSource::BuiltIn(name.clone())
                    .load(&[])
                    .ok()?;
                Some(SceneDoc {
                    kind: scene.chart.kind().to_string(),
                    title: scene.title,
                    name,
                })
            })
            .collect()
    });
    json_response(docs)
}

/// `GET /`: the page.
async fn page() -> Response {
    (
        [
            (header::CONTENT_TYPE, "text/html; charset=utf-8"),
            (
                header::CONTENT_SECURITY_POLICY,
                "default-src 'self'; img-src 'self' data: blob:; style-src 'self' \
                 'unsafe-inline'; script-src 'self' 'unsafe-inline'; connect-src 'self'",
            ),
            (header::X_CONTENT_TYPE_OPTIONS, "nosniff"),
        ],
        super::PAGE,
    )
        .into_response()
}

/// `GET /gallery.js`: the gallery's read-off script, which the page uses for its chart.
async fn gallery_js() -> Response {
    (
        [(header::CONTENT_TYPE, "text/javascript; charset=utf-8")],
        crate::charts::GALLERY_JS,
    )
        .into_response()
}

async fn not_found() -> Response {
    http_refusal(
        StatusCode::NOT_FOUND,
        None,
        "no such route: the page is /, the API /api/v1/{solve,design,vlocator,render,settings,\
         scenes}",
    )
}

async fn wrong_method() -> Response {
    http_refusal(
        StatusCode::METHOD_NOT_ALLOWED,
        None,
        "solve, design and vlocator take POST with a JSON body; the rest GET",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::serve::Limits;

    fn on_runtime(f: impl std::future::Future<Output = ()>) {
        tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .unwrap()
            .block_on(f);
    }

    /// Every slot taken and no room to wait: 503 at once, with when to come back.
    #[test]
    fn a_full_server_says_come_back_instead_of_queueing() {
        on_runtime(async {
            let limits = Limits {
                slots: 1,
                queue: 0,
                ..Limits::default()
            };
            let shared = Arc::new(Shared::new(limits, None, None));
            let held = shared.slots.clone().try_acquire_owned().unwrap();
            let r = work(&shared, || Ok(1)).await.unwrap_err();
            assert_eq!(r.status(), StatusCode::SERVICE_UNAVAILABLE);
            assert_eq!(r.headers()[header::RETRY_AFTER], "1");
            drop(held);
            assert_eq!(work(&shared, || Ok(1)).await.ok(), Some(1));
        });
    }

    /// An answer past the time limit is a 503 naming the limit; its slot stays taken until
    /// the work ends, so the slots still bound what runs.
    #[test]
    fn an_answer_past_its_time_limit_is_refused_and_keeps_its_slot() {
        on_runtime(async {
            let limits = Limits {
                slots: 1,
                time_limit: std::time::Duration::from_millis(50),
                ..Limits::default()
            };
            let shared = Arc::new(Shared::new(limits, None, None));
            let (tx, rx) = std::sync::mpsc::channel::<()>();
            let r = work(&shared, move || {
                let _ = rx.recv();
                Ok(())
            })
            .await
            .unwrap_err();
            assert_eq!(r.status(), StatusCode::SERVICE_UNAVAILABLE);
            assert_eq!(shared.slots.available_permits(), 0, "the work still runs");
            tx.send(()).unwrap();
            let _slot = shared.slots.acquire().await.unwrap();
        });
    }

    /// The budget bounds what a question may ask: a sampled answer over its CPU estimate is
    /// refused before any sample, as a cost (413), naming the key that sets it.
    #[test]
    fn work_over_the_budget_is_refused_with_its_estimate() {
        on_runtime(async {
            let shared = Arc::new(Shared::new(Limits::default(), None, None));
            let r = work(&shared, || {
                let kw = Keywords::from_json(serde_json::json!({
                    "mu": "normal(0.3,0.01)", "model": "min-norm", "samples": 1_000_000
                }))?;
                SolveQuestion::from_keywords(kw)?.answer()
            })
            .await
            .unwrap_err();
            assert_eq!(r.status(), StatusCode::PAYLOAD_TOO_LARGE);
        });
    }
}
