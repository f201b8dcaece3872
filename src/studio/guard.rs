//! What keeps other web pages out of the studio.
//!
//! The studio listens on this machine, but every web page the user visits can send requests
//! to `127.0.0.1`: a page on another origin can post forms and `no-cors` `fetch`es (which a
//! browser sends without asking the server first when the content type is `text/plain`), and a
//! page whose DNS name is re-pointed at `127.0.0.1` ("DNS rebinding") can read the replies as
//! its own. A local tool that writes laser jobs must not be steered or read that way, so
//! [`check`] runs before every route and refuses, with `403` and a JSON `{"error": …}` saying
//! why:
//!
//! 1. **a foreign `Host`**: every request must name the address served, `127.0.0.1:PORT`,
//!    `localhost:PORT` or `[::1]:PORT` with the port actually bound (or the bound address
//!    itself; when bound to all interfaces, any IP literal with that port). A rebinding page's
//!    requests carry its own DNS name, so they read nothing.
//! 2. **a state-changing request (`POST`, `PUT`, `PATCH`, `DELETE`) from elsewhere**: one
//!    whose `Origin` is present and not `http://` + an address of 1, whose `Sec-Fetch-Site` is
//!    present and neither `same-origin` nor `none`, or which does not carry the page's token
//!    ([`TOKEN_HEADER`]). The token is drawn at launch from the operating system's random
//!    source and written into the page ([`Guard::page`]); the page's `api.js` sends it with
//!    every call. A header that is not CORS-safelisted cannot be sent by another origin
//!    without a preflight, which the studio never answers, and the other origin cannot read
//!    the page to learn the token.
//!
//! Routes that read a JSON body take it through [`JsonBody`], which refuses (`415`) any body
//! whose `Content-Type` is not `application/json`. Uploads keep whatever type the browser
//! gives the file (`text/plain` for a `.txt`, `image/png`, none for a `.fold`): the token and
//! the origin checks guard them.
//!
//! [`security_headers`] adds to every response (page, asset, API reply, error):
//! [`CONTENT_SECURITY_POLICY`] (scripts, styles, images and connections from the studio
//! itself only, no inline script or style, no framing, no forms, no plug-ins),
//! `X-Frame-Options: DENY`, `X-Content-Type-Options: nosniff` and `Referrer-Policy:
//! no-referrer`.

use std::convert::Infallible;
use std::hash::{BuildHasher, Hasher};
use std::net::SocketAddr;
use std::sync::Arc;

use axum::body::Bytes;
use axum::extract::{FromRequest, Request, State};
use axum::http::{HeaderMap, HeaderValue, Method, StatusCode, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use super::api::{ApiError, ApiResult};

/// The request header that carries the page's per-launch token.
pub const TOKEN_HEADER: &str = "x-foldcam-token";

/// Where the page's `<meta name="foldcam-token">` holds the token; replaced when served.
const TOKEN_PLACEHOLDER: &str = "FOLDCAM-PAGE-TOKEN";

/// The policy sent with every response: the page loads its own modules, style sheet and
/// three.js from the studio and talks to the studio only.
pub const CONTENT_SECURITY_POLICY: &str = "default-src 'none'; script-src 'self'; \
     style-src 'self'; img-src 'self'; connect-src 'self'; base-uri 'none'; \
     form-action 'none'; frame-ancestors 'none'";

/// The addresses the studio answers to and its token.
pub struct Guard {
    /// `host:port` strings accepted in `Host` (lower case).
    hosts: Vec<String>,
    /// When bound to all interfaces: any IP literal with this port is accepted too.
    any_ip_port: Option<u16>,
    token: String,
}

impl Guard {
    /// The guard of a studio bound to `bound`, with a fresh token.
    pub fn new(bound: SocketAddr) -> Guard {
        let port = bound.port();
        let mut hosts = vec![
            format!("127.0.0.1:{port}"),
            format!("localhost:{port}"),
            format!("[::1]:{port}"),
        ];
        let own = SocketAddr::new(bound.ip(), port).to_string().to_lowercase();
        if !hosts.contains(&own) {
            hosts.push(own);
        }
        Guard {
            hosts,
            any_ip_port: bound.ip().is_unspecified().then_some(port),
            token: new_token(),
        }
    }

    /// The page `html` with its token placeholder replaced by this launch's token.
    pub fn page(&self, html: &str) -> String {
        html.replace(TOKEN_PLACEHOLDER, &self.token)
    }

    /// Whether `host` (a `Host` header or a URL's authority) names the address served.
    pub fn is_own_host(&self, host: &str) -> bool {
        let host = host.to_ascii_lowercase();
        if self.hosts.contains(&host) {
            return true;
        }
        self.any_ip_port.is_some_and(|port| {
            host.parse::<SocketAddr>()
                .is_ok_and(|a| a.port() == port && !a.ip().is_unspecified())
        })
    }

    /// Whether `origin` (an `Origin` header) is the studio's own page.
    pub fn is_own_origin(&self, origin: &str) -> bool {
        origin
            .strip_prefix("http://")
            .is_some_and(|host| self.is_own_host(host))
    }

    /// Why `headers` (of a request with `method`) are refused, or `None` to let it through.
    pub fn refusal(
        &self,
        method: &Method,
        uri_host: Option<&str>,
        headers: &HeaderMap,
    ) -> Option<String> {
        let host = headers
            .get(header::HOST)
            .map(|h| h.to_str().unwrap_or("(not text)"));
        let served = self.hosts.first().map(String::as_str).unwrap_or_default();
        match host {
            None => {
                return Some(format!(
                    "the request names no Host: open the studio at http://{served}/"
                ));
            }
            Some(h) if !self.is_own_host(h) => {
                return Some(format!(
                    "Host {h} is not this studio's address (http://{served}/): refused, so that \
                     a web page that points its own name at this machine cannot read the studio"
                ));
            }
            Some(_) => {}
        }
        if let Some(h) = uri_host.filter(|h| !self.is_own_host(h)) {
            return Some(format!(
                "the request is addressed to {h}, not to this studio (http://{served}/)"
            ));
        }
        if !changes_state(method) {
            return None;
        }
        if let Some(origin) = headers.get(header::ORIGIN) {
            let origin = origin.to_str().unwrap_or("(not text)");
            if !self.is_own_origin(origin) {
                return Some(format!(
                    "{method} from the web page at {origin}: only the studio's own page \
                     (http://{served}/) may change its documents"
                ));
            }
        }
        if let Some(site) = headers.get("sec-fetch-site") {
            let site = site.to_str().unwrap_or("(not text)");
            if site != "same-origin" && site != "none" {
                return Some(format!(
                    "{method} sent by a {site} web page: only the studio's own page \
                     (http://{served}/) may change its documents"
                ));
            }
        }
        let token = headers.get(TOKEN_HEADER).map(HeaderValue::as_bytes);
        if token != Some(self.token.as_bytes()) {
            return Some(format!(
                "{method} without the studio page's token ({TOKEN_HEADER}): only the page \
                 served by this launch of the studio may change its documents (reload the page \
                 at http://{served}/)"
            ));
        }
        None
    }
}

/// `POST`, `PUT`, `PATCH` and `DELETE`: the methods a route may change state on.
fn changes_state(method: &Method) -> bool {
    [Method::POST, Method::PUT, Method::PATCH, Method::DELETE].contains(method)
}

/// 128 bits from the operating system's random source (the keys std seeds each
/// `RandomState` with), as 32 hexadecimal digits.
fn new_token() -> String {
    let mut out = String::with_capacity(32);
    for salt in 0u64..2 {
        let mut h = std::collections::hash_map::RandomState::new().build_hasher();
        h.write_u64(salt);
        out.push_str(&format!("{:016x}", h.finish()));
    }
    out
}

/// Middleware: refuses (403) what [`Guard::refusal`] refuses, else runs the route.
pub async fn check(State(guard): State<Arc<Guard>>, request: Request, next: Next) -> Response {
    let uri_host = request.uri().authority().map(|a| a.as_str().to_string());
    match guard.refusal(request.method(), uri_host.as_deref(), request.headers()) {
        Some(why) => ApiError::new(StatusCode::FORBIDDEN, why).into_response(),
        None => next.run(request).await,
    }
}

/// Middleware: the security headers of the module's contract on every response.
pub async fn security_headers(mut response: Response) -> Response {
    let h = response.headers_mut();
    h.insert(
        header::CONTENT_SECURITY_POLICY,
        HeaderValue::from_static(CONTENT_SECURITY_POLICY),
    );
    h.insert(header::X_FRAME_OPTIONS, HeaderValue::from_static("DENY"));
    h.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    h.insert(
        header::REFERRER_POLICY,
        HeaderValue::from_static("no-referrer"),
    );
    response
}

/// A request body that must be JSON: `Content-Type: application/json` (parameters such as
/// `charset` allowed), else 415 when read by [`super::edit_api::json_body`]. Extraction never
/// fails by itself so that the route's own error names the request.
pub struct JsonBody(pub ApiResult<Bytes>);

impl<S: Send + Sync> FromRequest<S> for JsonBody {
    type Rejection = Infallible;

    async fn from_request(request: Request, state: &S) -> Result<Self, Self::Rejection> {
        if let Err(e) = require_json(request.headers()) {
            return Ok(JsonBody(Err(e)));
        }
        let body = Bytes::from_request(request, state)
            .await
            .map_err(|r| ApiError::new(r.status(), r.body_text()));
        Ok(JsonBody(body))
    }
}

/// `Ok` when `headers` declare a JSON body; else 415 saying what was sent.
pub fn require_json(headers: &HeaderMap) -> ApiResult<()> {
    let sent = headers
        .get(header::CONTENT_TYPE)
        .map(|v| v.to_str().unwrap_or("(not text)"));
    let essence = sent
        .and_then(|t| t.split(';').next())
        .map(|t| t.trim().to_ascii_lowercase());
    if essence.as_deref() == Some("application/json") {
        return Ok(());
    }
    Err(ApiError::new(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        format!(
            "the request body must be JSON sent with Content-Type: application/json (it was {})",
            sent.map_or("sent without a Content-Type".to_string(), |t| format!(
                "sent as {t}"
            ))
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guard() -> Guard {
        Guard::new("127.0.0.1:8470".parse().unwrap())
    }

    #[test]
    fn hosts_of_the_bound_port_only() {
        let g = guard();
        for ok in [
            "127.0.0.1:8470",
            "localhost:8470",
            "LOCALHOST:8470",
            "[::1]:8470",
        ] {
            assert!(g.is_own_host(ok), "{ok}");
        }
        for bad in [
            "attacker.example:8470",
            "127.0.0.1:8471",
            "127.0.0.1",
            "localhost",
            "localhost.attacker.example:8470",
            "10.0.0.2:8470",
        ] {
            assert!(!g.is_own_host(bad), "{bad}");
        }
        let all = Guard::new("0.0.0.0:9000".parse().unwrap());
        assert!(all.is_own_host("192.168.1.20:9000"));
        assert!(!all.is_own_host("rebind.example:9000"));
        assert!(!all.is_own_host("192.168.1.20:9001"));
    }

    #[test]
    fn origins_and_tokens() {
        let g = guard();
        assert!(g.is_own_origin("http://localhost:8470"));
        assert!(!g.is_own_origin("null"));
        assert!(!g.is_own_origin("http://127.0.0.1:9999"));
        assert!(!g.is_own_origin("https://127.0.0.1:8470"));
        assert_eq!(g.token.len(), 32);
        assert_ne!(g.token, guard().token);
        assert!(
            g.page("<meta content=\"FOLDCAM-PAGE-TOKEN\">")
                .contains(&g.token)
        );
    }

    #[test]
    fn json_content_type() {
        let mut h = HeaderMap::new();
        assert!(require_json(&h).is_err());
        h.insert(header::CONTENT_TYPE, HeaderValue::from_static("text/plain"));
        assert!(require_json(&h).is_err());
        h.insert(
            header::CONTENT_TYPE,
            HeaderValue::from_static("Application/JSON; charset=utf-8"),
        );
        assert!(require_json(&h).is_ok());
    }
}
