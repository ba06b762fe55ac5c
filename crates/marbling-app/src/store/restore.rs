//! What the page's storage gives back at start-up: the newest readable autosave, the
//! text of one that cannot be read (to keep, with why), the preferences, the noise
//! playground's spec and the recent designs. Reading storage never touches the app:
//! `MarblingApp::new` applies what is found.

use crate::store::autosave::{self, Record};
use crate::store::prefs::{self, Prefs};
use crate::store::recent::{self, Recent};
use marbling_noise::NoiseSpec;

/// Everything found in storage.
#[derive(Default)]
pub(crate) struct Stored {
    /// The newest readable autosave.
    pub(crate) autosave: Option<Record>,
    /// Autosaves that could not be read: their text (when still there) and why.
    pub(crate) unreadable: Vec<(Option<String>, String)>,
    /// The preferences (`Err`: why the stored ones were not taken).
    pub(crate) prefs: Option<Result<Prefs, String>>,
    /// The noise playground's spec (`Err`: why it was not read).
    pub(crate) noise: Option<Result<NoiseSpec, String>>,
    /// The recent designs.
    pub(crate) recent: Option<Recent>,
}

/// Reads storage through `load` (a key's text, if any); `defaults` fill the
/// preferences' missing fields.
pub(crate) fn read(load: impl Fn(&str) -> Option<String>, defaults: &Prefs) -> Stored {
    let found = autosave::newest(
        [load(autosave::SLOTS[0]), load(autosave::SLOTS[1])],
        load(autosave::LEGACY_KEY),
    );
    Stored {
        autosave: found.record,
        unreadable: found
            .unreadable
            .into_iter()
            .map(|(key, why)| (load(&key), why))
            .collect(),
        prefs: load(prefs::KEY).map(|text| Prefs::decode(&text, defaults)),
        noise: load(crate::noise::settings::KEY)
            .map(|text| NoiseSpec::from_json(&text).map_err(|e| e.to_string())),
        recent: load(recent::KEY).map(|text| Recent::decode(&text)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    #[test]
    fn an_unreadable_autosave_is_kept_with_why_and_the_rest_is_read() {
        let design = crate::store::file_panel::blank([20, 10]);
        let stored: HashMap<&str, String> = HashMap::from([
            (
                autosave::SLOTS[0],
                "{\"seq\":9,\"saved\":0,\"link\":\"d=%%\"}".to_owned(),
            ),
            (
                crate::noise::settings::KEY,
                "{\"type\":\"nope\"}".to_owned(),
            ),
        ]);
        let s = read(|k| stored.get(k).cloned(), &Prefs::default());
        assert!(s.autosave.is_none());
        assert_eq!(s.unreadable.len(), 1);
        assert_eq!(
            s.unreadable[0].0.as_deref(),
            Some(stored[autosave::SLOTS[0]].as_str())
        );
        assert!(
            s.unreadable[0].1.contains("base64url"),
            "{}",
            s.unreadable[0].1
        );
        assert!(matches!(s.noise, Some(Err(_))));
        assert!(s.prefs.is_none() && s.recent.is_none());
        // With a readable older copy the torn newer one costs nothing.
        let mut stored = stored;
        stored.insert(autosave::SLOTS[1], autosave::encode(3, 0.0, &design));
        stored.insert(prefs::KEY, "{".to_owned());
        let s = read(|k| stored.get(k).cloned(), &Prefs::default());
        assert_eq!(s.autosave.expect("the readable slot").design, design);
        assert!(s.unreadable.is_empty());
        assert!(matches!(s.prefs, Some(Err(_))));
    }
}
