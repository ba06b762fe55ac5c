//! Keyboard and screen-reader access. Every control takes keyboard focus with Tab
//! (Shift+Tab goes back) and Enter or Space presses it; the focused control is drawn
//! with egui's focus ring and named in `data-focus`. On the desktop, eframe's AccessKit
//! gives screen readers the controls; in the browser, where eframe has no AccessKit
//! bridge, *Read controls aloud* (Alt+Shift+R) has the browser's speech synthesis say each
//! control as it takes focus, and the canvas's `aria-label` tells a screen reader how.

use egui::{Key, KeyboardShortcut, Modifiers, Rect};

/// Alt+Shift+R turns reading the controls aloud on and off.
pub const READ_ALOUD: KeyboardShortcut =
    KeyboardShortcut::new(Modifiers::ALT.plus(Modifiers::SHIFT), Key::R);

/// Whether the focused control is read aloud (eframe's web screen reader).
pub fn reading_aloud(ctx: &egui::Context) -> bool {
    ctx.options(|o| o.screen_reader)
}

/// Turns reading aloud on or off.
pub fn set_reading_aloud(ctx: &egui::Context, on: bool) {
    ctx.options_mut(|o| o.screen_reader = on);
}

/// Toggles reading aloud when its shortcut was pressed.
pub fn handle_shortcut(ctx: &egui::Context) {
    if ctx.input_mut(|i| i.consume_shortcut(&READ_ALOUD)) {
        set_reading_aloud(ctx, !reading_aloud(ctx));
    }
}

/// The name of the control with keyboard focus: the named control (`data-controls`)
/// drawn where the focused widget is.
pub fn focused_control<'a>(
    ctx: &egui::Context,
    controls: impl IntoIterator<Item = (&'a str, Rect)>,
) -> Option<&'a str> {
    let id = ctx.memory(|m| m.focused())?;
    let rect = ctx.read_response(id)?.rect;
    controls
        .into_iter()
        .find(|(_, r)| *r == rect)
        .map(|(name, _)| name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tab_moves_focus_between_controls_and_the_hook_names_it() {
        let ctx = egui::Context::default();
        // One frame with `events`; the named control with focus after it.
        let frame = |events: Vec<egui::Event>| {
            let input = egui::RawInput {
                events,
                ..Default::default()
            };
            let mut named = Vec::new();
            ctx.run_ui(input, |ui| {
                named.push(("undo", ui.button("Undo").rect));
                named.push(("redo", ui.button("Redo").rect));
            })
            .textures_delta
            .clear();
            focused_control(&ctx, named).map(str::to_owned)
        };
        let tab = || {
            vec![egui::Event::Key {
                key: Key::Tab,
                physical_key: None,
                pressed: true,
                repeat: false,
                modifiers: Modifiers::NONE,
            }]
        };
        assert_eq!(frame(vec![]), None);
        frame(tab());
        let first = frame(vec![]);
        frame(tab());
        let second = frame(vec![]);
        assert_eq!(first.as_deref(), Some("undo"));
        assert_eq!(second.as_deref(), Some("redo"));
    }

    #[test]
    fn the_shortcut_toggles_reading_aloud() {
        let ctx = egui::Context::default();
        assert!(!reading_aloud(&ctx));
        let press = egui::Event::Key {
            key: Key::R,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: Modifiers::ALT | Modifiers::SHIFT,
        };
        let input = egui::RawInput {
            events: vec![press],
            ..Default::default()
        };
        ctx.run_ui(input, |ui| handle_shortcut(ui.ctx()))
            .textures_delta
            .clear();
        assert!(reading_aloud(&ctx));
    }
}
