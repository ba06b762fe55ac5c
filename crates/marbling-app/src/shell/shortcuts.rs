//! The keyboard shortcuts of a frame: undo (Ctrl+Z) and redo (Ctrl+Shift+Z, Ctrl+Y),
//! every press counted however many arrive in one frame (a slow frame on a software
//! GPU collects several); the number keys 1–9 and 0 pick the first ten tools; reading
//! aloud (see `accessibility`). The frame loop applies what was pressed.

use crate::marbling::tools::{TOOL_KEYS, ToolKind};
use egui::{Key, Modifiers};

/// What the keyboard asked for in one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Pressed {
    /// Redo presses (taken first: undo's shortcut would match them too).
    pub(crate) redos: usize,
    /// Undo presses.
    pub(crate) undos: usize,
    /// The tool a number key picked (only when no text field has focus).
    pub(crate) tool: Option<ToolKind>,
}

/// Reads (and consumes) this frame's shortcuts.
pub(crate) fn read(ctx: &egui::Context) -> Pressed {
    crate::shell::accessibility::handle_shortcut(ctx);
    let (redos, undos) = ctx.input_mut(|i| {
        (
            i.count_and_consume_key(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z)
                + i.count_and_consume_key(Modifiers::COMMAND, Key::Y),
            i.count_and_consume_key(Modifiers::COMMAND, Key::Z),
        )
    });
    let tool = if ctx.egui_wants_keyboard_input() {
        None
    } else {
        TOOL_KEYS
            .into_iter()
            .zip(ToolKind::ALL)
            .rev()
            .find(|(key, _)| ctx.input(|i| i.key_pressed(*key) && i.modifiers.is_none()))
            .map(|(_, tool)| tool)
    };
    Pressed { redos, undos, tool }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(key: Key, modifiers: Modifiers) -> egui::Event {
        egui::Event::Key {
            key,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers,
        }
    }

    fn frame(events: Vec<egui::Event>) -> Pressed {
        let ctx = egui::Context::default();
        let mut pressed = Pressed::default();
        // The keys held down, as a browser reports them before the key.
        let held = match events.first() {
            Some(egui::Event::Key { modifiers, .. }) => *modifiers,
            _ => Modifiers::NONE,
        };
        let events = std::iter::once(egui::Event::ModifiersChanged(held))
            .chain(events)
            .collect();
        let input = egui::RawInput {
            events,
            ..Default::default()
        };
        ctx.run_ui(input, |ui| pressed = read(ui.ctx()))
            .textures_delta
            .clear();
        pressed
    }

    #[test]
    fn every_press_of_a_slow_frame_counts() {
        let undo = key(Key::Z, Modifiers::COMMAND);
        let redo = key(Key::Z, Modifiers::COMMAND | Modifiers::SHIFT);
        let p = frame(vec![undo.clone(), undo.clone(), redo, undo]);
        assert_eq!((p.undos, p.redos), (3, 1));
        let p = frame(vec![key(Key::Y, Modifiers::COMMAND)]);
        assert_eq!((p.undos, p.redos), (0, 1));
    }

    #[test]
    fn number_keys_pick_tools() {
        assert_eq!(
            frame(vec![key(Key::Num2, Modifiers::NONE)]).tool,
            Some(ToolKind::ALL[1])
        );
        assert_eq!(
            frame(vec![key(Key::Num0, Modifiers::NONE)]).tool,
            Some(ToolKind::ALL[9])
        );
        assert_eq!(frame(vec![key(Key::Num2, Modifiers::COMMAND)]).tool, None);
        assert_eq!(frame(vec![]), Pressed::default());
    }
}
