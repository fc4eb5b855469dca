//! What a drawing did, kept for the tests: a thread-local list that drawing code appends to
//! while a test records (a drawing runs on one thread, so the list sees exactly its own).

use std::cell::RefCell;
use std::thread::LocalKey;

/// A thread-local recording: None while no test records.
pub type Tape<T> = RefCell<Option<Vec<T>>>;

/// Appends `item()` to `tape` while a recording runs (the item is built only then).
pub fn note<T: 'static>(tape: &'static LocalKey<Tape<T>>, item: impl FnOnce() -> T) {
    tape.with_borrow_mut(|t| {
        if let Some(t) = t {
            t.push(item());
        }
    });
}

/// Runs `draw` and returns, beside its result, what it noted on `tape`, in order.
#[cfg(test)]
pub fn record<T: 'static, R>(
    tape: &'static LocalKey<Tape<T>>,
    draw: impl FnOnce() -> R,
) -> (R, Vec<T>) {
    let outer = tape.with_borrow_mut(|t| t.replace(Vec::new()));
    let r = draw();
    let noted = tape.with_borrow_mut(|t| std::mem::replace(t, outer));
    (r, noted.unwrap_or_default())
}
