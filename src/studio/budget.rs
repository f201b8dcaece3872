//! The memory the studio's large requests may hold at once: each reserves its estimate
//! (a voxel card by its pattern cells, a tessellation solve by the solver's estimate) before
//! it allocates, and gives it back when done. A request that would pass
//! [`STUDIO_MEMORY_BYTES`] is refused — 503 while others hold the memory (it may be sent again
//! later), 422 when it is larger than the whole budget — so concurrent requests never exhaust
//! the machine and abort the server.

use std::sync::{Mutex, PoisonError};

use axum::http::StatusCode;

use super::api::{ApiError, ApiResult};
use crate::limits::STUDIO_MEMORY_BYTES;

/// A budget of bytes and what requests under way hold of it.
#[derive(Debug)]
pub(super) struct Budget {
    total: u64,
    held: Mutex<u64>,
}

/// The studio's budget.
static STUDIO: Budget = Budget::new(STUDIO_MEMORY_BYTES);

/// Memory held by one request; given back when dropped.
#[derive(Debug)]
pub(super) struct Reservation {
    budget: &'static Budget,
    bytes: u64,
}

impl Drop for Reservation {
    fn drop(&mut self) {
        let mut held = self.budget.held();
        *held = held.saturating_sub(self.bytes);
    }
}

/// Reserves `bytes` for `what` (named in the refusal) out of the studio's budget.
pub(super) fn reserve(what: &str, bytes: u64) -> ApiResult<Reservation> {
    STUDIO.reserve(what, bytes)
}

impl Budget {
    const fn new(total: u64) -> Budget {
        Budget {
            total,
            held: Mutex::new(0),
        }
    }

    fn held(&self) -> std::sync::MutexGuard<'_, u64> {
        self.held.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Reserves `bytes` for `what`, or says why not.
    fn reserve(&'static self, what: &str, bytes: u64) -> ApiResult<Reservation> {
        let mb = |b: u64| b.div_ceil(1_000_000);
        let total = self.total;
        if bytes > total {
            return Err(ApiError::input(format!(
                "{what} would need about {} MB, more than the {} MB the studio gives its \
                 requests: make it smaller, or use the command line",
                mb(bytes),
                mb(total)
            )));
        }
        let mut held = self.held();
        if held.saturating_add(bytes) > total {
            return Err(ApiError::new(
                StatusCode::SERVICE_UNAVAILABLE,
                format!(
                    "{what} would need about {} MB while other requests hold {} of the \
                     studio's {} MB: try again when they are done",
                    mb(bytes),
                    mb(*held),
                    mb(total)
                ),
            ));
        }
        *held += bytes;
        Ok(Reservation {
            budget: self,
            bytes,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reservations_beyond_the_budget_are_refused_until_memory_is_given_back() {
        static SMALL: Budget = Budget::new(1_000);
        let a = SMALL.reserve("a", 600).expect("fits");
        let busy = SMALL.reserve("b", 600).expect_err("the rest is held");
        assert_eq!(busy.status, StatusCode::SERVICE_UNAVAILABLE);
        let huge = SMALL.reserve("c", 1_001).expect_err("too large");
        assert_eq!(huge.status, StatusCode::UNPROCESSABLE_ENTITY);
        drop(a);
        let b = SMALL.reserve("b", 600).expect("given back");
        assert_eq!(*SMALL.held(), 600);
        drop(b);
        assert_eq!(*SMALL.held(), 0);
    }
}
