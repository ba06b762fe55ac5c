//! Which arrangement of the playground fits the screen: the side panel on desktops, a
//! bottom sheet under the canvas on portrait screens (phones, tablets held upright), or a
//! narrow tool rail beside the canvas on landscape phones.

use egui::Vec2;

/// Portrait screens up to this width (CSS px) get the bottom sheet.
pub const PORTRAIT_MAX_WIDTH: f32 = 820.0;
/// Landscape touch screens up to this height (CSS px) get the tool rail.
pub const LANDSCAPE_MAX_HEIGHT: f32 = 500.0;
/// Smallest height and width of a control in the touch layouts, CSS px.
pub const TOUCH_TARGET: f32 = 44.0;
/// The desktop side panel's width, points: one width whatever its content (rows that
/// need more wrap), so picking a tool never moves the canvas.
pub const PANEL_WIDTH: f32 = 300.0;
/// The open bottom sheet (tabs and content) takes at most this share of the screen's
/// height, so the canvas keeps more than half of it with the status bar.
pub const SHEET_MAX_FRACTION: f32 = 0.34;
/// Width of the tool rail, CSS px.
pub const RAIL_WIDTH: f32 = 92.0;

/// The arrangement of panels around the canvas.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// Side panel on the left, status bar below.
    Desktop,
    /// Canvas on top; the controls in a bottom sheet with tabs that can be collapsed.
    Portrait,
    /// A narrow tool rail beside the canvas; the full panel opens from it (touch
    /// screens only: a short desktop window keeps its side panel).
    Landscape,
}

impl Layout {
    /// The layout for a screen of `size` CSS px; `touch_screen` when it takes touches
    /// (`platform::touch_screen`).
    pub fn for_screen(size: Vec2, touch_screen: bool) -> Self {
        if size.x <= PORTRAIT_MAX_WIDTH && size.y > size.x {
            Layout::Portrait
        } else if touch_screen && size.y <= LANDSCAPE_MAX_HEIGHT && size.x > size.y {
            Layout::Landscape
        } else {
            Layout::Desktop
        }
    }

    /// The name shown in `data-layout`.
    pub fn name(self) -> &'static str {
        match self {
            Layout::Desktop => "desktop",
            Layout::Portrait => "portrait",
            Layout::Landscape => "landscape",
        }
    }

    /// True for the layouts made for fingers.
    pub fn touch(self) -> bool {
        self != Layout::Desktop
    }
}

/// Makes every control of `ui` at least [`TOUCH_TARGET`] high (and buttons as wide).
pub fn touch_spacing(ui: &mut egui::Ui) {
    let s = ui.spacing_mut();
    s.interact_size = egui::vec2(TOUCH_TARGET, TOUCH_TARGET);
    s.button_padding = egui::vec2(10.0, 6.0);
    s.icon_width = 22.0;
    s.icon_width_inner = 12.0;
    s.slider_width = s.slider_width.max(140.0);
    s.item_spacing = egui::vec2(8.0, 6.0);
}

/// A button of the status bar: small on a desktop, finger-sized on touch layouts.
pub(crate) fn status_button(ui: &mut egui::Ui, touch: bool, text: &str) -> egui::Response {
    if touch {
        ui.button(text)
    } else {
        ui.small_button(text)
    }
}

/// The bottom sheet's tabs: each shows part of the side panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SheetTab {
    /// The tools and their settings.
    Tools,
    /// Palette, ink and paper colours.
    Ink,
    /// Undo, redo, the gesture list and the player.
    History,
    /// New, open, save, share, export and recent designs.
    Files,
    /// The noise playground.
    Noise,
}

impl SheetTab {
    /// The tabs in their order on screen.
    pub const ALL: [SheetTab; 5] = [
        SheetTab::Tools,
        SheetTab::Ink,
        SheetTab::History,
        SheetTab::Files,
        SheetTab::Noise,
    ];

    /// The tab's title.
    pub fn label(self) -> &'static str {
        match self {
            SheetTab::Tools => "Tools",
            SheetTab::Ink => "Ink",
            SheetTab::History => "History",
            SheetTab::Files => "Files",
            SheetTab::Noise => "Noise",
        }
    }

    /// The tab's control name in `data-controls` (`sheet-tools` …).
    pub fn control(self) -> &'static str {
        match self {
            SheetTab::Tools => "sheet-tools",
            SheetTab::Ink => "sheet-ink",
            SheetTab::History => "sheet-history",
            SheetTab::Files => "sheet-files",
            SheetTab::Noise => "sheet-noise",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::vec2;

    #[test]
    fn phones_and_tablets_get_their_layouts() {
        assert_eq!(
            Layout::for_screen(vec2(390.0, 844.0), true),
            Layout::Portrait
        );
        assert_eq!(
            Layout::for_screen(vec2(820.0, 1180.0), true),
            Layout::Portrait
        );
        assert_eq!(
            Layout::for_screen(vec2(844.0, 390.0), true),
            Layout::Landscape
        );
        assert_eq!(
            Layout::for_screen(vec2(1440.0, 900.0), false),
            Layout::Desktop
        );
        assert_eq!(
            Layout::for_screen(vec2(1300.0, 820.0), true),
            Layout::Desktop
        );
        // A tablet held sideways has room for the side panel; a short desktop window
        // keeps it too.
        assert_eq!(
            Layout::for_screen(vec2(1180.0, 820.0), true),
            Layout::Desktop
        );
        assert_eq!(
            Layout::for_screen(vec2(760.0, 480.0), false),
            Layout::Desktop
        );
        assert!(Layout::Portrait.touch() && !Layout::Desktop.touch());
    }

    #[test]
    fn touch_spacing_makes_44_px_targets() {
        let ctx = egui::Context::default();
        let mut height = 0.0;
        ctx.run_ui(Default::default(), |ui| {
            touch_spacing(ui);
            height = ui.button("Undo").rect.height();
        })
        .textures_delta
        .clear();
        assert!(height >= TOUCH_TARGET, "{height}");
    }
}
