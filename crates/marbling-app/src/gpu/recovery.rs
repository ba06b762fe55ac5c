//! Surviving a lost GPU device (a driver reset, a WebGL context taken away, a WebGPU
//! device destroyed): the app notices, parks its editing state here, and the page's
//! start-up loop (`main.rs`, wasm32) tears the renderer down and starts a fresh one on a
//! new canvas, which picks the parked state up. The design, its undo/redo history and
//! the tool settings survive; only GPU resources are rebuilt.
//!
//! Natively eframe cannot reopen its window's device, so the app says what happened and
//! relies on the autosave (written after every op) instead.

use crate::History;
use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};

/// What an app hands over to its successor after the device was lost.
#[derive(Clone, Debug)]
pub struct ParkedState {
    /// The design with its undo/redo stacks.
    pub history: History,
    /// Tool, tool settings, palette, ink and antialiasing.
    pub prefs: crate::store::prefs::Prefs,
    /// The fragment already loaded (so the successor does not reload the link).
    pub last_fragment: Option<String>,
}

thread_local! {
    static PARKED: RefCell<Option<ParkedState>> = const { RefCell::new(None) };
}

/// Set by the app when its device is gone; the start-up loop restarts the renderer.
static RESTART: AtomicBool = AtomicBool::new(false);

/// How many times the renderer was restarted (shown as `data-recovered`).
static RECOVERIES: AtomicU32 = AtomicU32::new(0);

/// Restarts since the last exact frame was drawn.
static IN_A_ROW: AtomicU32 = AtomicU32::new(0);

/// Restarts in a row (with no exact frame drawn between them) after which the page
/// stops trying: a design whose frames outlast the driver's watchdog would otherwise
/// lose the device forever.
pub const MAX_RESTARTS_IN_A_ROW: u32 = 3;

/// Parks `state` and asks for a restart.
pub fn park(state: ParkedState) {
    PARKED.with(|p| *p.borrow_mut() = Some(state));
    RESTART.store(true, Ordering::SeqCst);
}

/// The parked state, once (the new app takes it).
pub fn take_parked() -> Option<ParkedState> {
    PARKED.with(|p| p.borrow_mut().take())
}

/// True once after [`park`]: the caller must restart the renderer now.
pub fn take_restart_request() -> bool {
    let asked = RESTART.swap(false, Ordering::SeqCst);
    if asked {
        RECOVERIES.fetch_add(1, Ordering::SeqCst);
        IN_A_ROW.fetch_add(1, Ordering::SeqCst);
    }
    asked
}

/// The renderer drew an exact frame: the restarts so far succeeded.
pub fn note_drawn() {
    IN_A_ROW.store(0, Ordering::SeqCst);
}

/// True when the renderer was restarted more than [`MAX_RESTARTS_IN_A_ROW`] times
/// without drawing a frame between: the start-up loop gives up and says so.
pub fn give_up() -> bool {
    IN_A_ROW.load(Ordering::SeqCst) > MAX_RESTARTS_IN_A_ROW
}

/// Restarts so far.
pub fn recoveries() -> u32 {
    RECOVERIES.load(Ordering::SeqCst)
}

/// A flag raised when the device is lost (the reason is logged, not kept).
#[derive(Clone, Debug, Default)]
pub struct LostFlag(Arc<AtomicBool>);

impl LostFlag {
    /// Raises the flag.
    pub fn raise(&self) {
        self.0.store(true, Ordering::SeqCst);
    }

    /// True once the device is lost.
    pub fn is_raised(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }

    /// Watches `device` (and on the web, the page's canvas for `webglcontextlost`):
    /// raises the flag and wakes the UI when it is lost.
    pub fn watch(&self, device: &wgpu::Device, ctx: &egui::Context) {
        let flag = self.clone();
        let ctx_lost = ctx.clone();
        device.set_device_lost_callback(move |reason, message| {
            log::warn!("GPU device lost ({reason:?}): {message}");
            flag.raise();
            ctx_lost.request_repaint();
        });
        #[cfg(target_arch = "wasm32")]
        crate::platform::on_context_lost({
            let flag = self.clone();
            let ctx = ctx.clone();
            move || {
                flag.raise();
                ctx.request_repaint();
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::marbling::tools::{ToolKind, ToolSettings};
    use marbling_core::{Antialias, Design, Rgb8};

    #[test]
    fn parked_state_is_handed_over_once_with_one_restart() {
        let history = History::new(Design::new(10, 10, Rgb8::new(1, 2, 3)));
        assert!(!take_restart_request());
        park(ParkedState {
            history: history.clone(),
            prefs: crate::store::prefs::Prefs {
                tool: ToolKind::Comb,
                settings: ToolSettings::default(),
                palette: 2,
                imported: None,
                ink: Rgb8::new(9, 9, 9),
                antialias: Antialias::Grid4,
            },
            last_fragment: None,
        });
        let before = recoveries();
        assert!(take_restart_request());
        assert!(!take_restart_request());
        assert_eq!(recoveries(), before + 1);
        // Restarts that never reach a drawn frame are given up on after a few.
        note_drawn();
        for _ in 0..MAX_RESTARTS_IN_A_ROW {
            RESTART.store(true, Ordering::SeqCst);
            assert!(take_restart_request());
            assert!(!give_up());
        }
        RESTART.store(true, Ordering::SeqCst);
        assert!(take_restart_request());
        assert!(give_up());
        note_drawn();
        assert!(!give_up());
        let parked = take_parked().expect("parked");
        assert_eq!(parked.history, history);
        assert_eq!(parked.prefs.tool, ToolKind::Comb);
        assert!(take_parked().is_none());
    }

    #[test]
    fn the_lost_flag_is_shared_by_its_clones() {
        let flag = LostFlag::default();
        let other = flag.clone();
        assert!(!flag.is_raised());
        other.raise();
        assert!(flag.is_raised());
    }
}
