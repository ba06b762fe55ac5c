//! What is kept in the page's storage, and what is owed to it: the autosave, the
//! preferences, the noise setup and *Recent designs*, written at most once a second
//! ([`autosave::MIN_INTERVAL_MS`]) by [`Session::write_owed`] at the end of a frame.

use crate::noise::Noise;
use crate::platform;
use crate::store::autosave::{self, MIN_INTERVAL_MS, WRITE_AT_ONCE_OPS};
use crate::store::{prefs::Prefs, recent::Recent};
use marbling_core::Design;
use std::sync::Arc;

/// What is kept in the page's storage, and what is owed to it.
pub(crate) struct Session {
    /// True when the design changed since the last autosave.
    autosave_pending: bool,
    /// When the autosave was last written, ms since 1970.
    last_autosave_ms: f64,
    /// Storage writes waiting for a frame (key, value).
    pending_writes: Vec<(&'static str, String)>,
    /// The preferences last stored, and when (ms since 1970).
    stored_prefs: (Option<Prefs>, f64),
    /// The revision of the noise setup last stored.
    stored_noise: Option<u64>,
    /// *Recent designs*.
    recent: Recent,
    /// True when the recent list must be written.
    recent_pending: bool,
}

impl Default for Session {
    fn default() -> Self {
        Self {
            autosave_pending: false,
            last_autosave_ms: f64::NEG_INFINITY,
            pending_writes: Vec::new(),
            stored_prefs: (None, f64::NEG_INFINITY),
            stored_noise: None,
            recent: Recent::default(),
            recent_pending: false,
        }
    }
}

impl Session {
    /// What storage held at start-up: these preferences, this noise revision and this
    /// recent list need no writing.
    pub fn restored(&mut self, prefs: &Prefs, noise_revision: u64, recent: Option<Recent>) {
        self.stored_prefs.0 = Some(prefs.clone());
        self.stored_noise = Some(noise_revision);
        if let Some(recent) = recent {
            self.recent = recent;
        }
    }

    /// Writes `value` under `key` in the next frame.
    pub fn keep(&mut self, key: &'static str, value: String) {
        self.pending_writes.push((key, value));
    }

    /// The design changed: it is autosaved soon.
    pub fn design_changed(&mut self) {
        self.autosave_pending = true;
    }

    /// The design is autosaved in this frame, whatever the once-a-second rule says (the
    /// GPU device was lost).
    pub fn autosave_now(&mut self) {
        self.autosave_pending = true;
        self.last_autosave_ms = f64::NEG_INFINITY;
    }

    /// True when the design changed since the last autosave.
    pub fn owes_autosave(&self) -> bool {
        self.autosave_pending
    }

    /// True when the recent list is owed to storage.
    #[cfg(test)]
    pub fn owes_recent(&self) -> bool {
        self.recent_pending
    }

    /// *Recent designs*.
    pub fn recent(&self) -> &Recent {
        &self.recent
    }

    /// Keeps `design` in *Recent designs* (written in the next frame).
    pub fn keep_recent(&mut self, design: &Design, label: String) {
        self.recent.push(design, label, platform::now_ms());
        self.recent_pending = true;
    }

    /// Writes what storage is owed: waiting writes, the preferences and noise setup when
    /// changed, the recent list, and the autosave of `design` (at most one every
    /// [`MIN_INTERVAL_MS`]; the page-hide handler writes a waiting one when the page goes
    /// away). A full storage drops the oldest recent designs first, then says the design
    /// was not autosaved. Returns what went wrong, for the status line.
    pub fn write_owed(
        &mut self,
        frame: &mut eframe::Frame,
        ctx: &egui::Context,
        prefs: &Prefs,
        noise: &Noise,
        design: &Arc<Design>,
    ) -> Vec<String> {
        let mut problems = Vec::new();
        let now = platform::now_ms();
        let changed = self.stored_prefs.0.as_ref() != Some(prefs);
        if changed && now - self.stored_prefs.1 >= MIN_INTERVAL_MS {
            self.keep(crate::store::prefs::KEY, prefs.encode());
            self.stored_prefs = (Some(prefs.clone()), now);
        } else if changed {
            ctx.request_repaint_after(std::time::Duration::from_secs(1));
        }
        if self.stored_noise != Some(noise.revision()) {
            let json = noise.settings().export_spec().to_value().to_string();
            self.keep(crate::noise::settings::KEY, json);
            self.stored_noise = Some(noise.revision());
        }
        for (key, value) in std::mem::take(&mut self.pending_writes) {
            if let Err(e) = platform::store_string(frame, key, &value) {
                problems.push(format!("{key}: {e}"));
            }
        }
        if std::mem::take(&mut self.recent_pending) {
            while let Err(e) =
                platform::store_string(frame, crate::store::recent::KEY, &self.recent.encode())
            {
                if !self.recent.drop_oldest() {
                    problems.push(format!("recent designs were not saved: {e}"));
                    break;
                }
            }
        }
        if !self.autosave_pending {
            return problems;
        }
        let at_once = design.ops.len() <= WRITE_AT_ONCE_OPS;
        let wait = self.last_autosave_ms + MIN_INTERVAL_MS - now;
        if wait > 0.0 && !at_once {
            let mut u = autosave::unsaved();
            if u.design.as_ref().is_none_or(|d| !Arc::ptr_eq(d, design)) {
                u.design = Some(design.clone());
            }
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(wait / 1000.0));
            return problems;
        }
        self.autosave_pending = false;
        self.last_autosave_ms = now;
        let mut u = autosave::unsaved();
        u.design = None;
        let seq = u.seq + 1;
        let text = autosave::encode(seq, now, design);
        let mut result = platform::store_string(frame, autosave::slot(seq), &text);
        while result.is_err() && self.recent.drop_oldest() {
            let _ = platform::store_string(frame, crate::store::recent::KEY, &self.recent.encode());
            result = platform::store_string(frame, autosave::slot(seq), &text);
        }
        match result {
            Ok(()) => u.seq = seq,
            Err(e) => {
                drop(u);
                problems.push(format!(
                    "the design was not autosaved ({e}): use Save JSON to keep it"
                ));
            }
        }
        problems
    }
}
