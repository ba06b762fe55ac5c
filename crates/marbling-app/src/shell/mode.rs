//! Which side of the playground is open: marbling or the noise playground, and the
//! switch at the side panel's top.

use crate::action::Action;
use crate::frame::Frame;
use egui::RichText;

/// Which side of the playground is open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Marbling: the design and its tools.
    Marbling,
    /// The noise playground.
    Noise,
}

impl Mode {
    /// The name shown in `data-mode`: `marbling` or `noise`.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Marbling => "marbling",
            Mode::Noise => "noise",
        }
    }
}

/// The side panel's *Marbling* | *Noise* switch.
pub(crate) fn switch_ui(ui: &mut egui::Ui, f: &mut Frame<'_>) {
    ui.horizontal(|ui| {
        let mut mode = f.editor.mode;
        let heading = |text: &str| RichText::new(text).heading();
        let m = ui.selectable_value(&mut mode, Mode::Marbling, heading("Marbling"));
        f.control("mode-marbling", &m);
        let n = ui.selectable_value(&mut mode, Mode::Noise, heading("Noise"));
        f.control("mode-noise", &n);
        if mode != f.editor.mode {
            f.act(Action::SetMode(mode));
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_what_automation_reads() {
        assert_eq!(Mode::Marbling.name(), "marbling");
        assert_eq!(Mode::Noise.name(), "noise");
    }
}
