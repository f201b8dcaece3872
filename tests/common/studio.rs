//! Running `foldcam serve` from the studio tests: the binary on a free port, and plain HTTP/1.1
//! over a TCP socket (so the requests are exactly the bytes written here, `..` included).
#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// How long a test waits for one reply.
pub const REPLY_TIMEOUT: Duration = Duration::from_secs(120);

/// A running `foldcam serve`, stopped when dropped.
pub struct Server {
    child: Child,
    /// The address it listens on.
    pub addr: SocketAddr,
    /// This launch's page token (from the page's `<meta name="foldcam-token">`), sent by
    /// [`Server::raw`] as the page's `api.js` sends it.
    pub token: String,
}

/// A whole reply: status, header lines (names in lower case) and the body (de-chunked).
pub struct Reply {
    pub status: u16,
    pub headers: Vec<(String, String)>,
    pub body: Vec<u8>,
}

impl Reply {
    /// The value of header `name` (lower case), if sent.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

impl Server {
    /// Starts `foldcam serve --port 0 ARGS` in `dir` and reads the address it prints first.
    pub fn start(args: &[&str], dir: &Path) -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
            .arg("serve")
            .args(["--port", "0"])
            .args(args)
            .current_dir(dir)
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("foldcam serve starts");
        let mut line = String::new();
        BufReader::new(child.stdout.take().expect("stdout"))
            .read_line(&mut line)
            .expect("the server prints its address");
        let url = line
            .trim()
            .strip_prefix("foldcam studio: http://")
            .unwrap_or_else(|| panic!("unexpected first line {line:?}"));
        let addr = url.trim_end_matches('/').parse().expect("an address");
        let mut server = Server {
            child,
            addr,
            token: String::new(),
        };
        let (_, page) = server.get("/");
        let page = String::from_utf8_lossy(&page);
        server.token = page
            .split("<meta name=\"foldcam-token\" content=\"")
            .nth(1)
            .and_then(|rest| rest.split('"').next())
            .unwrap_or_default()
            .to_string();
        server
    }

    /// Sends exactly `head` (request line and headers, without the blank line) with
    /// `Connection: close`, `Content-Length` and `body`: the whole reply.
    pub fn exact(&self, head: &str, body: &[u8]) -> Reply {
        let head = format!(
            "{head}\r\nConnection: close\r\nContent-Length: {}",
            body.len()
        );
        full_reply(&self.send(&head, body))
    }

    /// The page's URL.
    pub fn url(&self) -> String {
        format!("http://{}/", self.addr)
    }

    /// Sends `head` (request line and headers, without the blank line) and `body` as the
    /// studio's page does: with the `Host` served, the page's token and (unless `head` names
    /// one) `Content-Type: application/json`; returns the status code and the body.
    pub fn raw(&self, head: &str, body: &[u8]) -> (u16, Vec<u8>) {
        let content_type = if head.to_ascii_lowercase().contains("\r\ncontent-type:") {
            ""
        } else {
            "Content-Type: application/json\r\n"
        };
        let head = format!(
            "{head}\r\nHost: {}\r\nX-Foldcam-Token: {}\r\n{content_type}Connection: close\r\n\
             Content-Length: {}",
            self.addr,
            self.token,
            body.len()
        );
        split_reply(&self.send(&head, body))
    }

    /// Sends `head` (without the blank line) and `body` on a new connection; the whole reply.
    fn send(&self, head: &str, body: &[u8]) -> Vec<u8> {
        let mut s = TcpStream::connect(self.addr).expect("connect");
        s.set_read_timeout(Some(REPLY_TIMEOUT)).unwrap();
        let mut request = format!("{head}\r\n\r\n").into_bytes();
        request.extend_from_slice(body);
        // A server may answer (413) before the whole body is sent and close: that is fine.
        let _ = s.write_all(&request);
        let mut reply = Vec::new();
        let _ = s.read_to_end(&mut reply);
        reply
    }
    /// `POST path` with `Expect: 100-continue`: the body is sent only when the server asks
    /// for it (so a refusal on the declared length is read before any body byte is sent).
    pub fn post_expecting(&self, path: &str, body: &[u8]) -> (u16, Vec<u8>) {
        let mut s = TcpStream::connect(self.addr).expect("connect");
        s.set_read_timeout(Some(REPLY_TIMEOUT)).unwrap();
        let head = format!(
            "POST {path} HTTP/1.1\r\nHost: {}\r\nX-Foldcam-Token: {}\r\nConnection: close\r\n\
             Expect: 100-continue\r\nContent-Length: {}\r\n\r\n",
            self.addr,
            self.token,
            body.len()
        );
        s.write_all(head.as_bytes()).unwrap();
        let mut reply = Vec::new();
        let mut byte = [0u8; 1];
        while !reply.ends_with(b"\r\n\r\n") {
            assert_eq!(
                s.read(&mut byte).expect("a reply"),
                1,
                "the server closed early"
            );
            reply.push(byte[0]);
        }
        if reply.starts_with(b"HTTP/1.1 100") {
            s.write_all(body).unwrap();
            reply.clear();
        }
        s.read_to_end(&mut reply).expect("the reply");
        split_reply(&reply)
    }

    /// `GET path`.
    pub fn get(&self, path: &str) -> (u16, Vec<u8>) {
        self.raw(&format!("GET {path} HTTP/1.1"), b"")
    }

    /// `POST path` with a body.
    pub fn post(&self, path: &str, body: &[u8]) -> (u16, Vec<u8>) {
        self.raw(&format!("POST {path} HTTP/1.1"), body)
    }

    /// `POST path` expecting JSON back.
    pub fn post_json(&self, path: &str, body: &[u8]) -> (u16, serde_json::Value) {
        let (status, body) = self.post(path, body);
        (status, serde_json::from_slice(&body).expect("a JSON reply"))
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Status, headers and body (de-chunked) of a whole HTTP reply.
fn full_reply(reply: &[u8]) -> Reply {
    let split = reply
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .unwrap_or_else(|| panic!("no HTTP reply: {reply:?}"));
    let head = String::from_utf8_lossy(&reply[..split]).into_owned();
    let headers: Vec<(String, String)> = head
        .lines()
        .skip(1)
        .filter_map(|l| l.split_once(':'))
        .map(|(n, v)| (n.trim().to_ascii_lowercase(), v.trim().to_string()))
        .collect();
    let (status, body) = split_reply(reply);
    Reply {
        status,
        headers,
        body,
    }
}

/// Status code and body (de-chunked) of a whole HTTP reply.
fn split_reply(reply: &[u8]) -> (u16, Vec<u8>) {
    let split = reply
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .unwrap_or_else(|| panic!("no HTTP reply: {reply:?}"));
    let headers = String::from_utf8_lossy(&reply[..split]).into_owned();
    let status = headers
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .expect("a status code");
    let mut body = reply[split + 4..].to_vec();
    if headers
        .to_ascii_lowercase()
        .contains("transfer-encoding: chunked")
    {
        body = dechunk(&body);
    }
    (status, body)
}

fn dechunk(mut body: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    loop {
        let Some(end) = body.windows(2).position(|w| w == b"\r\n") else {
            return out;
        };
        let size = usize::from_str_radix(std::str::from_utf8(&body[..end]).unwrap().trim(), 16)
            .expect("a chunk size");
        if size == 0 {
            return out;
        }
        out.extend_from_slice(&body[end + 2..end + 2 + size]);
        body = &body[end + 2 + size + 2..];
    }
}

/// Percent-encodes a query value.
pub fn encode(s: &str) -> String {
    s.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => {
                (b as char).to_string()
            }
            _ => format!("%{b:02X}"),
        })
        .collect()
}

/// `examples/patterns/flat-vertex.fold` folded all the way (its creases carry ±150°, a 3D
/// target the flat-foldability checks leave alone): mountains −180°, valleys +180°.
pub fn flat_vertex_folded_flat() -> Vec<u8> {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/patterns/flat-vertex.fold");
    let mut fold: serde_json::Value =
        serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let angles: Vec<f64> = fold["edges_assignment"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| match a.as_str().unwrap() {
            "M" => -180.0,
            "V" => 180.0,
            _ => 0.0,
        })
        .collect();
    fold["edges_foldAngle"] = serde_json::json!(angles);
    serde_json::to_vec_pretty(&fold).unwrap()
}
