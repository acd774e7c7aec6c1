//! `gyro-sim serve`: in come a scene with `[[controls]]` and the models; out goes a web server on
//! 127.0.0.1 serving one page (the 3-D view, sliders for the controls, the elevation plot) and
//! re-running the scene with the values the page sends. Each request is answered on a thread of
//! its own (a bounded number at once; more get a 503), a panic in one becoming a 500 for it alone.

mod api;
pub mod gate;
mod page;
mod plot_groups;
pub mod request;
mod title;

use std::io::Read;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

pub use api::{answer, run_data, App, Reply, RunDataError};
use thiserror::Error;

use crate::models::Registry;
use crate::scene::Scene;

/// Why the server could not start.
#[derive(Debug, Error)]
pub enum ServeError {
    /// The scene's own run, which the page is built around, failed.
    #[error("{}: {source}", scene.display())]
    Run {
        /// The scene file.
        scene: PathBuf,
        /// Why its run failed.
        #[source]
        source: RunDataError,
    },
    /// The port could not be listened on.
    #[error("cannot listen on 127.0.0.1:{port}: {source}")]
    Listen {
        /// The port asked for.
        port: u16,
        /// What the server library said.
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
}

/// Requests answered at once (after their bodies are read); more are answered 503 at once.
const MAX_ACTIVE: usize = 64;

/// How often the listener looks for a stop signal.
const POLL: Duration = Duration::from_millis(200);

/// The app for `scene`: its page, built around the scene's own run (an error when that run fails).
pub fn app(scene: Scene, registry: Registry) -> Result<App, ServeError> {
    let data = run_data(&scene, &registry)
        .map_err(|source| ServeError::Run { scene: scene.path.clone(), source })?;
    let page = page::page(&scene, &data);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    Ok(App { scene, registry, page, runs: gate::Gate::new(cores) })
}

/// Serves `app` on 127.0.0.1:`port` (0: a free port) until a stop signal; `started` is told the
/// address once it listens.
pub fn serve(app: App, port: u16, started: impl FnOnce(&str)) -> Result<(), ServeError> {
    let server =
        tiny_http::Server::http(("127.0.0.1", port)).map_err(|source| ServeError::Listen { port, source })?;
    let address = server.server_addr().to_ip().map_or("127.0.0.1".into(), |a| a.to_string());
    started(&address);
    let app = Arc::new(app);
    let active = Arc::new(AtomicUsize::new(0));
    while crate::ode::interrupt::requested().is_none() {
        let request = match server.recv_timeout(POLL) {
            Ok(Some(request)) => request,
            Ok(None) => continue,
            Err(_) => {
                std::thread::sleep(POLL);
                continue;
            }
        };
        let (app, active) = (Arc::clone(&app), Arc::clone(&active));
        // The thread reads the body first: a client stalled in sending it holds no answer slot.
        let _ =
            std::thread::Builder::new().name("request".into()).spawn(move || respond(request, &app, &active));
    }
    Ok(())
}

/// Reads one request's body (at most [`request::MAX_BODY`] bytes), then, in one of
/// [`MAX_ACTIVE`] answer slots (a 503 when none is free), answers and replies.
fn respond(mut request: tiny_http::Request, app: &App, active: &AtomicUsize) {
    let method = request.method().as_str().to_ascii_uppercase();
    let path = request.url().to_string();
    let reply = if request.body_length().is_some_and(|n| n > request::MAX_BODY) {
        request::too_large().into()
    } else {
        let mut body = Vec::new();
        let read = request.as_reader().take(request::MAX_BODY as u64 + 1).read_to_end(&mut body);
        match read {
            Err(e) => Reply::error(400, &format!("the request body could not be read: {e}")),
            Ok(_) if active.fetch_add(1, Ordering::SeqCst) >= MAX_ACTIVE => {
                active.fetch_sub(1, Ordering::SeqCst);
                Reply::error(503, "the server is answering too many requests: try again")
            }
            Ok(_) => {
                let reply = catch_unwind(AssertUnwindSafe(|| answer(app, &method, &path, &body)));
                active.fetch_sub(1, Ordering::SeqCst);
                reply.unwrap_or_else(|_| {
                    Reply::error(500, "the run stopped on an internal error; the server goes on")
                })
            }
        }
    };
    let _ = request.respond(response(reply));
}

/// The HTTP response of a reply: never cached, never framed or sniffed.
fn response(reply: Reply) -> tiny_http::Response<std::io::Cursor<Vec<u8>>> {
    // The length is known: sent as Content-Length, never chunked.
    let mut response = tiny_http::Response::from_data(reply.body)
        .with_status_code(reply.status)
        .with_chunked_threshold(usize::MAX);
    let mut headers = vec![
        ("Content-Type", reply.content_type.to_string()),
        ("Cache-Control", "no-store".to_string()),
        ("X-Content-Type-Options", "nosniff".to_string()),
        ("X-Frame-Options", "DENY".to_string()),
    ];
    if let Some(name) = reply.download {
        let safe: String = name.chars().filter(|c| c.is_ascii_alphanumeric() || "._-".contains(*c)).collect();
        headers.push(("Content-Disposition", format!("attachment; filename=\"{safe}\"")));
    }
    for (name, value) in headers {
        if let Ok(h) = tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response.add_header(h);
        }
    }
    response
}

#[cfg(test)]
mod tests;
