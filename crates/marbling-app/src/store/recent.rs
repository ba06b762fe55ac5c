//! *Recent designs*: every design that New, Open, a link or the gallery replaced, kept
//! in storage (compressed like a share link) with its date, so any of them can be
//! restored after a reload. Newest first, at most [`MAX_ENTRIES`].

use marbling_core::{Design, decode_share, share_fragment};
use serde_json::{Value, json};

/// Storage key of the list.
pub const KEY: &str = "marbling.recent.v1";
/// How many designs are kept; the oldest goes first.
pub const MAX_ENTRIES: usize = 24;

/// One kept design.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// When it was kept, milliseconds since 1970.
    pub saved_ms: f64,
    /// What replaced it, or where it came from ("before opening chevron").
    pub label: String,
    /// The design as a share-link fragment (`d=…`).
    pub fragment: String,
    /// Its op count and size, for the list.
    pub ops: usize,
    /// Width and height, design pixels.
    pub size: [u32; 2],
}

/// The list, newest first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Recent {
    /// The entries, newest first.
    pub entries: Vec<Entry>,
}

impl Recent {
    /// Reads the stored list; entries that cannot be read are skipped.
    pub fn decode(text: &str) -> Self {
        let Ok(Value::Array(items)) = serde_json::from_str::<Value>(text) else {
            return Self::default();
        };
        let entries = items
            .iter()
            .filter_map(|v| {
                Some(Entry {
                    saved_ms: v["saved"].as_f64()?,
                    label: v["label"].as_str()?.to_owned(),
                    fragment: v["link"].as_str()?.to_owned(),
                    ops: usize::try_from(v["ops"].as_u64()?).ok()?,
                    size: [
                        u32::try_from(v["width"].as_u64()?).ok()?,
                        u32::try_from(v["height"].as_u64()?).ok()?,
                    ],
                })
            })
            .take(MAX_ENTRIES)
            .collect();
        Self { entries }
    }

    /// The stored text.
    pub fn encode(&self) -> String {
        Value::Array(
            self.entries
                .iter()
                .map(|e| {
                    json!({"saved": e.saved_ms.round(), "label": e.label, "link": e.fragment,
                        "ops": e.ops, "width": e.size[0], "height": e.size[1]})
                })
                .collect(),
        )
        .to_string()
    }

    /// Keeps `design` as the newest entry (an identical newest entry is only re-dated).
    pub fn push(&mut self, design: &Design, label: impl Into<String>, now_ms: f64) {
        let fragment = share_fragment(design);
        self.entries.retain(|e| e.fragment != fragment);
        self.entries.insert(
            0,
            Entry {
                saved_ms: now_ms,
                label: label.into(),
                fragment,
                ops: design.ops.len(),
                size: [design.width, design.height],
            },
        );
        self.entries.truncate(MAX_ENTRIES);
    }

    /// Drops the oldest entry (to make room when storage is full); false when empty.
    pub fn drop_oldest(&mut self) -> bool {
        self.entries.pop().is_some()
    }

    /// The design of entry `i`.
    pub fn design(&self, i: usize) -> Result<Design, String> {
        let e = self.entries.get(i).ok_or("no such recent design")?;
        decode_share(&e.fragment).map_err(|e| format!("recent design: {e}"))
    }
}

/// A short local date and time for the list ("2026-12-01 19:42", UTC).
pub fn date_label(ms: f64) -> String {
    let secs = (ms / 1000.0).floor() as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // Civil date from days since 1970-01-01 (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}",
        rest / 3600,
        (rest % 3600) / 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn the_list_round_trips_keeps_the_newest_first_and_caps_its_length() {
        let mut r = Recent::default();
        for i in 0..30 {
            r.push(
                &random_design(i, 40, 30, 5, Mix::Mixed),
                format!("d{i}"),
                i as f64,
            );
        }
        assert_eq!(r.entries.len(), MAX_ENTRIES);
        assert_eq!(r.entries[0].label, "d29");
        let back = Recent::decode(&r.encode());
        assert_eq!(back, r);
        assert_eq!(
            back.design(0).expect("a value"),
            random_design(29, 40, 30, 5, Mix::Mixed)
        );
        // Keeping the same design again moves it to the top instead of doubling it.
        r.push(&random_design(20, 40, 30, 5, Mix::Mixed), "again", 99.0);
        assert_eq!(r.entries.len(), MAX_ENTRIES);
        assert_eq!(r.entries[0].label, "again");
        assert_eq!(Recent::decode("not json"), Recent::default());
    }

    #[test]
    fn dates_are_civil_utc() {
        assert_eq!(date_label(0.0), "1970-01-01 00:00");
        assert_eq!(date_label(1_796_154_120_000.0), "2026-12-01 19:42");
    }
}
