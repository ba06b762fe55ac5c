//! A panic never loses the design: the hook writes the autosave that waits (a design of
//! up to `autosave::WRITE_AT_ONCE_OPS` ops is stored on every edit already) and says so
//! in plain HTML, since the canvas no longer draws. `window.marblingPanic()` makes the
//! next frame panic, for the browser tests.

use std::sync::atomic::{AtomicBool, Ordering};

/// What the page says after a panic, when the design is in storage.
pub const KEPT: &str = "Something broke; your design is kept — reload the page to go on.";
/// What it says when the waiting autosave could not be written (its store was busy).
pub const LAST_KEPT: &str =
    "Something broke; your last autosave is kept — reload the page to go on.";

static PANIC_REQUESTED: AtomicBool = AtomicBool::new(false);

/// Asks the next frame to panic (the test hook `window.marblingPanic()`).
pub fn request_panic() {
    PANIC_REQUESTED.store(true, Ordering::SeqCst);
}

/// Panics when a test asked for it: called at the top of every frame.
pub fn panic_if_requested() {
    if PANIC_REQUESTED.swap(false, Ordering::SeqCst) {
        panic!("window.marblingPanic() asked for a panic");
    }
}

/// Writes the waiting autosave if its store is free; the message for the page.
pub fn keep_the_design() -> &'static str {
    if crate::store::autosave::try_flush(crate::platform::store_now) {
        KEPT
    } else {
        LAST_KEPT
    }
}

/// Installs the hook (before eframe's, which logs the panic and calls this one), and
/// `window.marblingPanic()`.
#[cfg(target_arch = "wasm32")]
pub fn install() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = keep_the_design();
        crate::platform::set_body_attribute("data-error", Some(message));
        crate::platform::set_body_attribute("data-panic", Some(&info.to_string()));
        crate::platform::show_alert(message);
        previous(info);
    }));
    crate::platform::expose_panic();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_requested_panic_happens_once_and_the_waiting_design_is_written() {
        request_panic();
        assert!(std::panic::catch_unwind(panic_if_requested).is_err());
        panic_if_requested();
        let design = std::sync::Arc::new(marbling_core::synth::random_design(
            3,
            64,
            48,
            10,
            marbling_core::synth::Mix::Mixed,
        ));
        crate::store::autosave::unsaved().design = Some(design.clone());
        let mut written = Vec::new();
        assert!(crate::store::autosave::try_flush(|k, v| {
            written.push((k.to_owned(), v.to_owned()));
            Ok(())
        }));
        let record = crate::store::autosave::Record::decode(&written[0].1).expect("a record");
        assert_eq!(record.design, *design);
        // With the store held (the panic came from inside it), nothing blocks.
        let held = crate::store::autosave::unsaved();
        assert!(!crate::store::autosave::try_flush(|_, _| Ok(())));
        drop(held);
    }
}
