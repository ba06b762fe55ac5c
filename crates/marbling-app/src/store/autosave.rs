//! Autosave records: the design with a sequence number and the time it was saved,
//! written alternately to two storage slots so that a write cut short (a crash, a
//! closed tab) leaves the previous copy whole; the reader takes the newest readable one.
//!
//! A design of at most [`WRITE_AT_ONCE_OPS`] ops is written in the frame of the edit
//! itself, before that frame is shown: whatever the screen shows survives a reload, a
//! closed tab or a crash. Larger designs are written at most once every
//! [`MIN_INTERVAL_MS`] (`Session::write_owed`, src/store/session.rs), the waiting one when the page is
//! hidden or the window closes, and by the panic hook (src/automation/panic_guard.rs).

use marbling_core::{Design, ImageBackground};
use serde_json::Value;
use std::sync::{Arc, Mutex, MutexGuard};

/// The two storage slots, written in turn.
pub const SLOTS: [&str; 2] = ["marbling.autosave.a", "marbling.autosave.b"];
/// Where earlier versions kept the autosave (a bare design document); read when
/// neither slot holds one.
pub const LEGACY_KEY: &str = "marbling.autosave.v1";
/// Where an autosave that could not be read is moved, so that nothing overwrites it.
pub const UNREADABLE_KEY: &str = "marbling.autosave.unreadable";
/// Shortest time between two autosave writes of a large design while edits keep coming,
/// milliseconds.
pub const MIN_INTERVAL_MS: f64 = 1000.0;
/// Largest design (ops) written at once on every edit: its record encodes in a few
/// milliseconds in a browser (`autosave::tests::encoding_cost`).
pub const WRITE_AT_ONCE_OPS: usize = 5_000;
/// Largest picture background (its `data:` URI, characters) an autosave holds whole:
/// the two slots share the browser's ~5 MB of storage, so a larger picture is kept at
/// [`AUTOSAVE_PICTURE_SIDE`] (*Save JSON* keeps it whole).
pub const AUTOSAVE_PICTURE_CHARS: usize = 1 << 20;
/// Longest side of a picture an autosave keeps downscaled, pixels.
pub const AUTOSAVE_PICTURE_SIDE: u32 = 1024;

/// One autosave record.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// Increases with every write; the larger one of the two slots is the newer.
    pub seq: u64,
    /// When it was written, milliseconds since 1970.
    pub saved_ms: f64,
    /// The design.
    pub design: Design,
}

impl Record {
    /// Reads a stored record; `Err` says why it is unreadable.
    pub fn decode(text: &str) -> Result<Record, String> {
        let v: Value = serde_json::from_str(text).map_err(|e| e.to_string())?;
        let seq = v["seq"].as_u64().ok_or("no \"seq\"")?;
        let saved_ms = v["saved"].as_f64().ok_or("no \"saved\"")?;
        let design = match v["link"].as_str() {
            Some(link) => marbling_core::decode_share(link).map_err(|e| e.to_string())?,
            None => Design::from_json(&v["design"].to_string()).map_err(|e| e.to_string())?,
        };
        Ok(Record {
            seq,
            saved_ms,
            design,
        })
    }
}

/// The stored text of a record of `design`: `{"seq":…,"saved":…,"link":"d=…"}`, the
/// design compressed as a share link's fragment, with the fastest DEFLATE (2.6× shorter
/// than the JSON for random 5,000-op designs, 5.8× for 100,000 spray droplets: such a
/// design fits twice in a browser's 5 MB of storage), its picture downscaled when larger
/// than [`AUTOSAVE_PICTURE_CHARS`]. Records of earlier versions hold the document itself
/// as `"design":{…}`; [`Record::decode`] reads both.
pub fn encode(seq: u64, saved_ms: f64, design: &Design) -> String {
    let stored = storable(design);
    format!(
        "{{\"seq\":{seq},\"saved\":{},\"link\":\"d={}\"}}",
        saved_ms.round(),
        marbling_core::encode_share_payload_fast(stored.as_ref().unwrap_or(design))
    )
}

/// `design` with its picture downscaled when too large for storage, else `None` (the
/// design as it is). The last downscaled picture is remembered: autosaves come every
/// second while editing, and the picture seldom changes.
fn storable(design: &Design) -> Option<Design> {
    type Memo = Option<(
        Arc<marbling_core::image_background::ImagePixels>,
        ImageBackground,
    )>;
    static LAST: Mutex<Memo> = Mutex::new(None);
    let image = design.background_image.as_ref()?;
    if image.source().len() <= AUTOSAVE_PICTURE_CHARS {
        return None;
    }
    // Never blocks: a panic hook may write an autosave while this lock is held.
    let Ok(mut last) = LAST.try_lock() else {
        let mut d = design.clone();
        d.background_image = Some(image.downscaled(AUTOSAVE_PICTURE_SIDE, 85));
        return Some(d);
    };
    let small = match &*last {
        Some((pixels, small)) if Arc::ptr_eq(pixels, image.pixels_arc()) => {
            small.with_fit(image.fit)
        }
        _ => {
            let small = image.downscaled(AUTOSAVE_PICTURE_SIDE, 85);
            *last = Some((image.pixels_arc().clone(), small.clone()));
            small
        }
    };
    let mut d = design.clone();
    d.background_image = Some(small);
    Some(d)
}

/// The slot a record with sequence number `seq` is written to.
pub fn slot(seq: u64) -> &'static str {
    SLOTS[(seq % 2) as usize]
}

/// The autosave's sequence number and the design not yet written: one per page (it
/// outlives a renderer restart), shared with the page-hide handler, which may run
/// between frames.
#[derive(Debug, Default)]
pub struct Unsaved {
    /// Sequence number of the last record written.
    pub seq: u64,
    /// The design waiting to be written, if any.
    pub design: Option<Arc<Design>>,
}

impl Unsaved {
    /// Writes the waiting design now, if any (the page is being hidden).
    pub fn flush(&mut self, store: impl FnOnce(&str, &str) -> Result<(), String>) {
        if let Some(d) = self.design.take() {
            let seq = self.seq + 1;
            if store(slot(seq), &encode(seq, crate::platform::now_ms(), &d)).is_ok() {
                self.seq = seq;
            }
        }
    }
}

static UNSAVED: Mutex<Unsaved> = Mutex::new(Unsaved {
    seq: 0,
    design: None,
});

/// The page's autosave state (a poisoned lock is taken over: the state stays usable).
pub fn unsaved() -> MutexGuard<'static, Unsaved> {
    UNSAVED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Writes the waiting autosave now if the store is free (a panic may have come from
/// inside it); false when it was busy. Never blocks.
pub fn try_flush(store: impl FnOnce(&str, &str) -> Result<(), String>) -> bool {
    match UNSAVED.try_lock() {
        Ok(mut u) => {
            u.flush(store);
            true
        }
        Err(std::sync::TryLockError::Poisoned(p)) => {
            p.into_inner().flush(store);
            true
        }
        Err(std::sync::TryLockError::WouldBlock) => false,
    }
}

/// Writes the waiting autosave when the page is hidden or closed (registered once).
pub fn flush_on_page_hide() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        crate::platform::on_page_hide(|| unsaved().flush(crate::platform::store_now))
    });
}

/// What start-up finds in storage.
#[derive(Debug, Default)]
pub struct Found {
    /// The newest readable record.
    pub record: Option<Record>,
    /// Slots (or the legacy key) whose text could not be read, with the reason;
    /// only those newer than the record matter (see [`newest`]).
    pub unreadable: Vec<(String, String)>,
}

/// The newest readable record among the two slots (their texts as stored), else the
/// legacy document. A slot that cannot be read is reported only when no older slot
/// could stand in for it.
pub fn newest(slots: [Option<String>; 2], legacy: Option<String>) -> Found {
    let mut found = Found::default();
    let mut records = Vec::new();
    for (key, text) in SLOTS.iter().zip(slots) {
        let Some(text) = text else { continue };
        match Record::decode(&text) {
            Ok(r) => records.push(r),
            Err(e) => found.unreadable.push(((*key).to_owned(), e)),
        }
    }
    found.record = records.into_iter().max_by_key(|r| r.seq);
    if found.record.is_none()
        && let Some(text) = legacy
    {
        match Design::from_json(&text) {
            Ok(design) => {
                found.record = Some(Record {
                    seq: 0,
                    saved_ms: 0.0,
                    design,
                })
            }
            Err(e) => found
                .unreadable
                .push((LEGACY_KEY.to_owned(), crate::shell::message::first_line(&e))),
        }
    }
    if found.record.is_some() {
        // The other slot was the older copy, torn while being replaced: nothing is lost.
        found.unreadable.clear();
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record's stored text.
    fn stored(r: &Record) -> String {
        encode(r.seq, r.saved_ms, &r.design)
    }

    /// index.html preloads the gallery's thumbnails only when no autosave is stored: it
    /// names the storage keys itself.
    #[test]
    fn the_page_knows_the_autosave_keys() {
        let page = include_str!("../../../../index.html");
        for key in SLOTS.iter().chain([&LEGACY_KEY]) {
            assert!(page.contains(&format!("'{key}'")), "index.html lacks {key}");
        }
    }
    use marbling_core::synth::{Mix, random_design};

    fn record(seq: u64, ops: usize) -> Record {
        Record {
            seq,
            saved_ms: 1_700_000_000_000.0 + seq as f64,
            design: random_design(seq, 64, 48, ops, Mix::Mixed),
        }
    }

    #[test]
    fn a_large_picture_is_autosaved_downscaled_and_a_small_one_whole() {
        // 1200×700 of noise: an incompressible PNG of ~2.5 MB, over the storable size.
        let mut photo = marbling_core::RgbaImage::filled(1200, 700, [0, 0, 0, 255]);
        let mut rng = marbling_core::synth::SplitMix64(5);
        for px in photo.pixels.chunks_exact_mut(4) {
            px[..3].copy_from_slice(&rng.next_u64().to_le_bytes()[..3]);
        }
        let png = photo.to_png().expect("png");
        let mut r = record(3, 40);
        r.design.set_background_image(Some(
            ImageBackground::from_file_bytes(&png, marbling_core::ImageFit::Contain)
                .expect("picture"),
        ));
        let text = stored(&r);
        assert!(text.len() < 2 << 20, "{} characters", text.len());
        let back = Record::decode(&text).expect("reads back");
        assert_eq!(back.design.ops, r.design.ops);
        let img = back.design.background_image.expect("the picture is kept");
        assert_eq!((img.pixels().width, img.pixels().height), (1024, 597));
        assert_eq!(img.fit, marbling_core::ImageFit::Contain);
        // A small picture is kept whole.
        let small = marbling_core::synth::test_photo(1, 64, 40)
            .to_png()
            .expect("png");
        r.design.set_background_image(Some(
            ImageBackground::from_file_bytes(&small, marbling_core::ImageFit::Cover)
                .expect("picture"),
        ));
        let back = Record::decode(&stored(&r)).expect("reads back");
        assert_eq!(back.design, r.design);
    }

    #[test]
    fn records_round_trip_and_alternate_slots() {
        let r = record(7, 20);
        assert_eq!(Record::decode(&stored(&r)).expect("a value"), r);
        assert_ne!(slot(7), slot(8));
        assert!(Record::decode("{\"seq\":1}").is_err());
        // A record of an earlier version (the document itself) is still read.
        let earlier = format!(
            "{{\"seq\":7,\"saved\":{},\"design\":{}}}",
            r.saved_ms,
            r.design.to_json_compact()
        );
        assert_eq!(Record::decode(&earlier).expect("a value"), r);
        // A damaged link names what is wrong.
        let bad = r#"{"seq":1,"saved":0,"link":"d=%%"}"#;
        assert!(Record::decode(bad).expect_err("bad").contains("base64url"));
    }

    /// Ops as the app commits them (rounded to what can matter).
    #[test]
    fn a_record_is_a_fraction_of_the_designs_json() {
        let mut r = record(3, 5000);
        r.design.ops = r.design.ops.iter().map(|op| op.rounded()).collect();
        let (text, json) = (stored(&r).len(), r.design.to_json_compact().len());
        assert!(2 * text < json, "record {text} chars, JSON {json}");
        assert_eq!(Record::decode(&stored(&r)).expect("a value"), r);
    }

    #[test]
    fn the_newest_readable_slot_wins_and_a_torn_write_loses_nothing() {
        let (old, new) = (record(4, 10), record(5, 12));
        let found = newest([Some(stored(&old)), Some(stored(&new))], None);
        assert_eq!(found.record.expect("a value"), new);
        // The newer write was cut short: the older copy is whole and is taken.
        let torn = stored(&new)[..40].to_owned();
        let found = newest([Some(stored(&old)), Some(torn)], None);
        assert_eq!(found.record.expect("a value"), old);
        assert!(found.unreadable.is_empty());
        // Nothing readable: the reason is reported.
        let found = newest([Some("{".into()), None], None);
        assert!(found.record.is_none());
        assert_eq!(found.unreadable[0].0, SLOTS[0]);
    }

    #[test]
    fn the_legacy_autosave_is_read_when_no_slot_holds_one() {
        let d = random_design(3, 30, 20, 5, Mix::Mixed);
        let found = newest([None, None], Some(d.to_json_compact()));
        assert_eq!(found.record.expect("a value").design, d);
        let found = newest([None, None], Some("[]".into()));
        assert!(found.record.is_none());
        assert_eq!(found.unreadable[0].0, LEGACY_KEY);
    }
}
