//! The editors' open sessions (fold sequence, voxel card, pop-up card, paper craft): each one
//! numbered as it opens, the oldest dropped first beyond a limit, so a page left open cannot
//! grow the server without bound.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex, PoisonError};

use axum::http::StatusCode;

use super::api::{ApiError, ApiResult};

/// Sessions of one editor, numbered from 0, at most `limit` kept.
pub(super) struct Sessions<T> {
    /// What a session is, for the error of a closed one ("voxel card").
    noun: &'static str,
    limit: usize,
    inner: Mutex<Inner<T>>,
}

struct Inner<T> {
    next: u64,
    open: VecDeque<(u64, Arc<Mutex<T>>)>,
}

impl<T> Sessions<T> {
    /// No session yet; `noun` names one in errors, `limit` is how many are kept.
    pub(super) fn new(noun: &'static str, limit: usize) -> Self {
        Sessions {
            noun,
            limit,
            inner: Mutex::new(Inner {
                next: 0,
                open: VecDeque::new(),
            }),
        }
    }

    /// Opens `session` under the next number, dropping the oldest beyond the limit.
    pub(super) fn add(&self, session: T) -> (u64, Arc<Mutex<T>>) {
        let mut s = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        let id = s.next;
        s.next += 1;
        let session = Arc::new(Mutex::new(session));
        s.open.push_back((id, Arc::clone(&session)));
        while s.open.len() > self.limit {
            s.open.pop_front();
        }
        (id, session)
    }

    /// The session numbered `id`.
    ///
    /// # Errors
    /// 404 naming the session when it was never opened or has been dropped.
    pub(super) fn get(&self, id: u64) -> ApiResult<Arc<Mutex<T>>> {
        let s = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        s.open
            .iter()
            .find(|(i, _)| *i == id)
            .map(|(_, x)| Arc::clone(x))
            .ok_or_else(|| {
                ApiError::new(
                    StatusCode::NOT_FOUND,
                    format!("{} {id} is not open (open it again)", self.noun),
                )
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oldest_session_is_dropped_beyond_the_limit() {
        let sessions = Sessions::new("card", 2);
        let ids: Vec<u64> = (0..3).map(|k| sessions.add(k).0).collect();
        assert_eq!(ids, vec![0, 1, 2]);
        assert!(sessions.get(0).is_err());
        assert_eq!(*sessions.get(1).unwrap().lock().unwrap(), 1);
        assert_eq!(*sessions.get(2).unwrap().lock().unwrap(), 2);
    }
}
