//! The panel's sections, listed once: the mode each shows in, the bottom-sheet tab that
//! holds it on a phone, and where the rules between them fall. The side panel shows the
//! mode's sections in this order; the bottom sheet shows those of the open tab.

use crate::shell::layout::SheetTab;
use crate::shell::mode::Mode;

/// A part of the panel, drawn by its feature.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Section {
    /// Gallery, New, Open, Save JSON, Copy link, the new sheet's size.
    File,
    /// Export PNG and SVG, the 3D view.
    Export,
    /// The noise playground's controls.
    Noise,
    /// The design's noise background and grain, with a way to remove them.
    Surface,
    /// The tool buttons and the selected tool's parameters.
    Tool,
    /// Palette, ink and paper colours.
    Ink,
    /// A picture as the background.
    Picture,
    /// Live video as the background.
    Video,
    /// MIDI in: notes make drops.
    Midi,
    /// Sound in: a meter of six bands, each driving a parameter.
    Sound,
    /// Undo, redo, the gesture list and the player.
    History,
    /// The designs that New, Open, a link or the gallery replaced.
    Recent,
}

/// Where a section shows.
struct Row {
    section: Section,
    /// Shown in the marbling and in the noise playground.
    marbling: bool,
    noise: bool,
    /// The bottom-sheet tab that holds it.
    tab: SheetTab,
    /// Sections of one group follow each other without a rule.
    group: u8,
}

const fn row(section: Section, marbling: bool, noise: bool, tab: SheetTab, group: u8) -> Row {
    Row {
        section,
        marbling,
        noise,
        tab,
        group,
    }
}

/// Every section, in panel order.
const ROWS: [Row; 12] = [
    row(Section::File, true, true, SheetTab::Files, 0),
    // The noise playground exports its own PNG (one Export PNG per tab).
    row(Section::Export, true, false, SheetTab::Files, 1),
    row(Section::Noise, false, true, SheetTab::Noise, 2),
    row(Section::Surface, true, false, SheetTab::Tools, 3),
    row(Section::Tool, true, false, SheetTab::Tools, 3),
    row(Section::Ink, true, false, SheetTab::Ink, 4),
    row(Section::Picture, true, false, SheetTab::Ink, 4),
    row(Section::Video, true, false, SheetTab::Ink, 4),
    row(Section::History, true, false, SheetTab::History, 5),
    // Below the history: a keyboard player's section, out of the way of the rest.
    row(Section::Midi, true, false, SheetTab::Ink, 6),
    row(Section::Sound, true, false, SheetTab::Ink, 7),
    row(Section::Recent, true, true, SheetTab::Files, 8),
];

/// The sections shown in `mode` (only those of `tab` when given: the bottom sheet), in
/// order, each with whether a rule comes before it.
pub(crate) fn shown(mode: Mode, tab: Option<SheetTab>) -> Vec<(Section, bool)> {
    let mut out = Vec::new();
    let mut last_group = None;
    for r in &ROWS {
        let in_mode = match mode {
            Mode::Marbling => r.marbling,
            Mode::Noise => r.noise,
        };
        if !in_mode || tab.is_some_and(|t| t != r.tab) {
            continue;
        }
        let rule = last_group.is_some_and(|g| g != r.group);
        out.push((r.section, rule));
        last_group = Some(r.group);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use Section::*;

    #[test]
    fn the_side_panel_shows_the_modes_sections_with_rules_between_groups() {
        assert_eq!(
            shown(Mode::Marbling, None),
            [
                (File, false),
                (Export, true),
                (Surface, true),
                (Tool, false),
                (Ink, true),
                (Picture, false),
                (Video, false),
                (History, true),
                (Midi, true),
                (Sound, true),
                (Recent, true),
            ]
        );
        assert_eq!(
            shown(Mode::Noise, None),
            [(File, false), (Noise, true), (Recent, true)]
        );
    }

    #[test]
    fn every_tab_holds_something_and_every_section_has_a_tab() {
        for tab in SheetTab::ALL {
            let mode = if tab == SheetTab::Noise {
                Mode::Noise
            } else {
                Mode::Marbling
            };
            assert!(!shown(mode, Some(tab)).is_empty(), "{tab:?} is empty");
        }
        for mode in [Mode::Marbling, Mode::Noise] {
            let mut in_tabs: Vec<Section> = SheetTab::ALL
                .iter()
                .flat_map(|&t| shown(mode, Some(t)))
                .map(|(s, _)| s)
                .collect();
            let mut all: Vec<Section> = shown(mode, None).into_iter().map(|(s, _)| s).collect();
            in_tabs.sort_by_key(|s| *s as u8);
            all.sort_by_key(|s| *s as u8);
            assert_eq!(in_tabs, all, "{mode:?}");
        }
        assert_eq!(
            shown(Mode::Marbling, Some(SheetTab::Files)),
            [(File, false), (Export, true), (Recent, true)]
        );
    }
}
