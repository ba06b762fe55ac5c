//! What the workspace's tests share (a dev-dependency only).
//!
//! * **The GPU-skip policy.** A GPU test that cannot open a device fails, with the fix in
//!   its message, unless `MARBLING_SKIP_GPU=1` asks to skip it; every skip is printed
//!   with a running count, so a run that skipped GPU tests says so loudly.
//! * **Where the goldens are**: `tests/snapshots/` at the workspace's root, one folder
//!   per crate (`core`, `gpu`, `noise`, `vector`).
//! * **The error-message assertion** ([`assert_listed`]): a refused document's messages
//!   (each naming its JSON path) include the expected one, word for word.
//! * **naga checks of WGSL** ([`wgsl`]): validation, and host structs against WGSL
//!   struct layouts, every member.

pub mod wgsl;

use std::fmt::Display;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The environment variable that lets GPU tests skip where no adapter opens.
pub const SKIP_GPU_VAR: &str = "MARBLING_SKIP_GPU";

static SKIPPED: AtomicUsize = AtomicUsize::new(0);

/// True when the environment asks to skip GPU tests (`MARBLING_SKIP_GPU=1`).
pub fn skip_requested() -> bool {
    std::env::var(SKIP_GPU_VAR).is_ok_and(|v| v == "1")
}

/// GPU tests skipped so far in this test binary.
pub fn skipped_gpu_tests() -> usize {
    SKIPPED.load(Ordering::SeqCst)
}

/// The device (or whatever needed one) when it opened; `None` when it did not and
/// skipping was asked for (printed, with the count so far). Panics otherwise, naming
/// the error and the fix.
pub fn gpu_or_skip<T, E: Display>(opened: Result<T, E>) -> Option<T> {
    match opened {
        Ok(v) => Some(v),
        Err(e) if skip_requested() => {
            let n = SKIPPED.fetch_add(1, Ordering::SeqCst) + 1;
            eprintln!("{SKIP_GPU_VAR}=1: SKIPPED GPU test ({n} in this binary so far): {e}");
            None
        }
        Err(e) => panic!(
            "GPU test cannot run: {e}. Install Mesa's lavapipe (make setup-gpu) or set \
             {SKIP_GPU_VAR}=1 to skip GPU tests"
        ),
    }
}

/// Asserts that `messages` (a refused document's errors, each naming its JSON path)
/// include `expected` word for word; the failure lists them all.
pub fn assert_listed(messages: &[String], expected: &str) {
    assert!(
        messages.iter().any(|m| m == expected),
        "wanted {expected:?} among {messages:#?}"
    );
}

/// The goldens of `area` (`core`, `gpu`, `noise`, `vector`): `tests/snapshots/AREA/`
/// at the workspace's root.
pub fn goldens(area: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/snapshots")
        .join(area)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_open_device_is_used_and_goldens_exist() {
        assert_eq!(gpu_or_skip::<_, String>(Ok(7)), Some(7));
        for area in ["core", "gpu", "noise", "vector"] {
            assert!(goldens(area).is_dir(), "{}", goldens(area).display());
        }
    }

    #[test]
    fn the_error_assertion_finds_only_the_exact_message() {
        let messages = vec!["ops[0].radius: must be > 0, got -1".to_owned()];
        assert_listed(&messages, "ops[0].radius: must be > 0, got -1");
        let near =
            std::panic::catch_unwind(|| assert_listed(&messages, "ops[0].radius: must be > 0"));
        assert!(near.is_err(), "a partial message passed");
    }

    #[test]
    fn a_missing_device_fails_unless_skipping_was_asked_for() {
        let failed = std::panic::catch_unwind(|| gpu_or_skip::<(), _>(Err("no adapter")));
        if skip_requested() {
            assert_eq!(failed.ok(), Some(None));
            assert!(skipped_gpu_tests() >= 1);
        } else {
            let message = failed.expect_err("no device must fail the test");
            let text = message
                .downcast_ref::<String>()
                .cloned()
                .unwrap_or_default();
            assert!(
                text.contains("no adapter") && text.contains(SKIP_GPU_VAR),
                "{text}"
            );
        }
    }
}
