//! The status line's message: what just happened, or what went wrong. An error stays
//! until the next edit; other news also goes after [`Message::SHOWN_S`].

/// A line shown in the status bar; errors also go to `data-error`.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// What happened.
    pub text: String,
    /// True for problems (shown in red until the next edit).
    pub error: bool,
    /// When it was first shown (egui's clock, seconds).
    pub since: Option<f64>,
}

impl Message {
    /// How long news other than an error stays in the status line, seconds.
    pub const SHOWN_S: f64 = 6.0;

    /// News of `text`.
    pub fn info(text: String) -> Self {
        Self {
            text,
            error: false,
            since: None,
        }
    }

    /// The problem `text`.
    pub fn error(text: String) -> Self {
        Self {
            text,
            error: true,
            since: None,
        }
    }

    /// Shown at `now` (seconds): whether it is still current, and when to look again
    /// (seconds from now) so that news goes on time even when nothing else moves.
    pub fn shown_at(&mut self, now: f64) -> (bool, Option<f64>) {
        let since = *self.since.get_or_insert(now);
        match self.error {
            true => (true, None),
            false if now - since > Self::SHOWN_S => (false, None),
            false => (true, Some(Self::SHOWN_S - (now - since) + 0.05)),
        }
    }
}

/// The first line of an error (the status bar is one line; the count of the rest is noted).
pub(crate) fn first_line(e: &marbling_core::DesignError) -> String {
    first_line_of(&e.to_string())
}

pub(crate) fn first_line_of(s: &str) -> String {
    let mut lines = s.lines();
    let first = lines.next().unwrap_or_default().to_owned();
    let more = lines.count();
    if more > 0 {
        format!("{first} (and {more} more)")
    } else {
        first
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn news_goes_after_six_seconds_an_error_stays() {
        let mut m = Message::info("opened Stone (battal)".into());
        assert_eq!(m.shown_at(10.0), (true, Some(6.05)));
        assert!(m.shown_at(15.0).0);
        assert_eq!(m.shown_at(16.1), (false, None));
        let mut e = Message::error("share link: not valid base64url".into());
        assert_eq!(e.shown_at(10.0), (true, None));
        assert_eq!(e.shown_at(100.0), (true, None));
    }
}
