//! *Print…* in the Export section: a sheet (A4, A3, US Letter, the 50×70 cm end-paper
//! sheet, or a size typed in mm, cm or inches), a DPI (150, 300, 600 or typed) and a
//! bleed in mm; *Export for print* renders the design covering the sheet with the bleed
//! around it (`marbling_core::print`), the PNG carrying the DPI — the pixels of
//! `marbling render --print SIZE --dpi D --bleed B` at the GPU's precision.

use crate::frame::Frame;
use crate::store::export::{MAX_APP_EXPORT_PIXELS, MAX_APP_EXPORT_SIDE, fits_in_app};
use egui::RichText;
use marbling_core::Design;
use marbling_core::print::{
    BLEED_RANGE_MM, DPI_RANGE, PAPER_PRESETS, PRINT_DPIS, Print, SIDE_RANGE_MM, SheetSize, Unit,
};

/// The print settings and whether they are shown.
pub(crate) struct PrintPanel {
    open: bool,
    /// Index into [`PAPER_PRESETS`] (turned to the design), or `None` for the typed size.
    preset: Option<usize>,
    /// The typed sheet, in `unit`s.
    custom: [f64; 2],
    unit: Unit,
    dpi: f64,
    bleed_mm: f64,
}

impl Default for PrintPanel {
    fn default() -> Self {
        Self {
            open: false,
            preset: Some(0),
            custom: [210.0, 297.0],
            unit: Unit::Mm,
            dpi: 300.0,
            bleed_mm: 3.0,
        }
    }
}

/// `mm` to a tenth, without a trailing `.0` (297, 215.9).
fn tenths(mm: f64) -> f64 {
    (mm * 10.0).round() / 10.0
}

/// The automation name of preset `i`'s button.
fn preset_control(i: usize) -> String {
    format!("print-{}", PAPER_PRESETS[i].name.to_ascii_lowercase())
}

impl PrintPanel {
    /// The print the settings describe for `design`.
    pub fn print(&self, design: &Design) -> Print {
        let sheet = match self.preset {
            Some(i) => PAPER_PRESETS[i].for_design(design),
            None => SheetSize {
                width_mm: self.custom[0] * self.unit.mm(),
                height_mm: self.custom[1] * self.unit.mm(),
            },
        };
        Print {
            sheet,
            dpi: self.dpi,
            bleed_mm: self.bleed_mm,
        }
    }

    /// The *Print…* toggle (in the Export row).
    pub fn toggle_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame) {
        let toggle = ui
            .selectable_label(self.open, "Print…")
            .on_hover_text("A PNG at a paper size and DPI, with a bleed");
        frame.control("print", &toggle);
        if toggle.clicked() {
            self.open = !self.open;
        }
    }

    /// When open, the settings and *Export for print* (below the Export row); returns
    /// the print to export when that is clicked. `busy`: an export is running.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        design: &Design,
        busy: bool,
        frame: &mut Frame,
    ) -> Option<Print> {
        if !self.open {
            return None;
        }
        ui.horizontal_wrapped(|ui| {
            ui.label("Sheet");
            for (i, preset) in PAPER_PRESETS.iter().enumerate() {
                let label = match preset.name {
                    "Endpaper" => "50×70 cm",
                    name => name,
                };
                let r = ui
                    .selectable_value(&mut self.preset, Some(i), label)
                    .on_hover_text(format!(
                        "{} × {} mm, turned to the design",
                        preset.short_mm, preset.long_mm
                    ));
                frame.control(preset_control(i), &r);
            }
            let r = ui.selectable_value(&mut self.preset, None, "Custom");
            frame.control("print-custom", &r);
        });
        if self.preset.is_none() {
            ui.horizontal_wrapped(|ui| {
                let range =
                    SIDE_RANGE_MM.start() / self.unit.mm()..=SIDE_RANGE_MM.end() / self.unit.mm();
                let w = ui.add(
                    egui::DragValue::new(&mut self.custom[0])
                        .range(range.clone())
                        .speed(1.0),
                );
                frame.control("print-width", &w);
                ui.label("×");
                let h = ui.add(
                    egui::DragValue::new(&mut self.custom[1])
                        .range(range)
                        .speed(1.0),
                );
                frame.control("print-height", &h);
                for unit in Unit::ALL {
                    let before = self.unit;
                    let r = ui.selectable_value(&mut self.unit, unit, unit.suffix());
                    frame.control(format!("print-unit-{}", unit.suffix()), &r);
                    if r.clicked() && before != unit {
                        // The same sheet in the new unit.
                        for side in &mut self.custom {
                            *side = *side * before.mm() / unit.mm();
                        }
                    }
                }
            });
        }
        ui.horizontal_wrapped(|ui| {
            ui.label("DPI");
            for dpi in PRINT_DPIS {
                let r = ui.selectable_value(&mut self.dpi, dpi, format!("{dpi}"));
                frame.control(format!("print-dpi-{dpi}"), &r);
            }
            let typed = ui.add(
                egui::DragValue::new(&mut self.dpi)
                    .range(DPI_RANGE)
                    .speed(1.0),
            );
            frame.control("print-dpi", &typed);
        });
        ui.horizontal(|ui| {
            ui.label("Bleed");
            let bleed = ui.add(
                egui::DragValue::new(&mut self.bleed_mm)
                    .range(BLEED_RANGE_MM)
                    .speed(0.1)
                    .suffix(" mm"),
            );
            frame.control("print-bleed", &bleed);
            ui.label(RichText::new("each side, more of the design").weak());
        });
        let print = self.print(design);
        let (w, h) = print.pixels();
        let pixels = u64::from(w) * u64::from(h);
        let fits = fits_in_app(w, h);
        ui.label(
            RichText::new(format!(
                "{} × {} mm · {w} × {h} px · {} MB",
                tenths(print.sheet.width_mm),
                tenths(print.sheet.height_mm),
                pixels * 4 / 1_000_000
            ))
            .weak(),
        );
        if !fits {
            ui.label(
                RichText::new(format!(
                    "Too large for the app (at most {MAX_APP_EXPORT_SIDE} px on the long side, {} megapixels): lower the DPI, or use marbling render --print {:.0}x{:.0}mm --dpi {}",
                    MAX_APP_EXPORT_PIXELS / 1_000_000,
                    print.sheet.width_mm,
                    print.sheet.height_mm,
                    print.dpi
                ))
                .color(ui.visuals().warn_fg_color),
            );
            return None;
        }
        if busy {
            return None;
        }
        let export = ui
            .button("Export for print")
            .on_hover_text(format!("{print}: the design covers the sheet, centred"));
        frame.control("print-export", &export);
        export.clicked().then_some(print)
    }
}
