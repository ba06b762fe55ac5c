//! The Export section: the PNG size, Export PNG and its progress (src/store/export.rs),
//! Export SVG, Export for print and the 3D view's switch. A PNG export moves on one tile
//! a frame ([`ExportPanel::advance`]) and is handed to the user when complete.

use crate::frame::Frame;
use crate::media::view3d::View3dWindow;
use crate::platform;
use crate::shell::mode::Mode;
use crate::store::export::{ExportSize, ExportStep, PngExport, export_file_name};
use crate::store::print_panel::PrintPanel;
use crate::store::svg_export::SvgExporter;
use egui::RichText;
use marbling_core::Design;
use marbling_core::print::Print;

/// The Export section's state: the chosen PNG size and the exports under way.
pub(crate) struct ExportPanel {
    /// The PNG size chosen.
    size: ExportSize,
    /// A PNG export in progress and the file name it will get.
    png: Option<(PngExport, String)>,
    /// Export SVG and its running trace.
    svg: SvgExporter,
}

impl Default for ExportPanel {
    fn default() -> Self {
        Self {
            size: ExportSize::Screen,
            png: None,
            svg: SvgExporter::default(),
        }
    }
}

impl ExportPanel {
    /// Draws the section; `print` and `view3d` are the windows it opens.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        gpu: &eframe::Frame,
        print: &mut PrintPanel,
        view3d: &mut View3dWindow,
        f: &mut Frame<'_>,
    ) {
        ui.label(RichText::new("Export").strong());
        ui.horizontal_wrapped(|ui| {
            ui.label("PNG size");
            for size in ExportSize::CHOICES {
                let r = ui.selectable_value(&mut self.size, size, size.label());
                f.control(size.control_name(), &r);
            }
        });
        let editor = f.editor;
        let design = editor.history.design();
        let size_text = match marbling_core::output_size(design, self.size.scale(design)) {
            Ok((w, h)) => format!("{w} × {h} px"),
            Err(e) => e.to_string(),
        };
        ui.horizontal_wrapped(|ui| {
            if let Some((export, _)) = &self.png {
                let (w, h) = export.size();
                ui.label(format!("rendering {w} × {h}…"));
                let cancel = ui.button("Cancel");
                f.control("export-cancel", &cancel);
                if cancel.clicked() {
                    self.png = None;
                    f.info("export cancelled");
                }
            } else {
                if self.svg.progress().is_none() {
                    let png = ui
                        .button("Export PNG")
                        .on_hover_text(format!("An exact render, {size_text}"));
                    f.control("export-png", &png);
                    if png.clicked() {
                        self.start_png(gpu, f);
                    }
                }
                self.svg.ui(ui, f);
            }
            print.toggle_ui(ui, f);
            let open3d = ui.selectable_label(view3d.open, "3D view").on_hover_text(
                "The design on a vase, sphere, cylinder, book or plane, exact at any zoom",
            );
            f.control("view3d", &open3d);
            if open3d.clicked() {
                view3d.open = !view3d.open;
            }
        });
        ui.label(RichText::new(size_text).weak());
        if let Some(asked) = print.ui(ui, design, self.busy(), f) {
            self.start_print(gpu, asked, f);
        }
    }

    /// True while a PNG or SVG export runs.
    fn busy(&self) -> bool {
        self.png.is_some() || self.svg.progress().is_some()
    }

    /// Starts Export PNG of the shown design (the noise, in the noise playground) at the
    /// chosen size.
    fn start_png(&mut self, gpu: &eframe::Frame, f: &mut Frame<'_>) {
        let Some(rs) = gpu.wgpu_render_state() else {
            f.error("Export PNG needs the GPU renderer, which is not available");
            return;
        };
        let editor = f.editor;
        let design: &Design = match editor.mode {
            Mode::Noise => &editor.shown.design,
            Mode::Marbling => editor.history.design(),
        };
        let scale = self.size.scale(design);
        match PngExport::start(&rs.device, &rs.queue, design, scale, f.prefs.antialias) {
            Ok(export) => {
                let name = export_file_name(design, export.size(), "png");
                let (w, h) = export.size();
                f.info(format!("exporting {w}×{h} PNG…"));
                self.png = Some((export, name));
            }
            Err(e) => f.error(format!("Export PNG: {e}")),
        }
    }

    /// Starts Export for print of the design: `print`'s window of it, the PNG carrying
    /// the DPI.
    fn start_print(&mut self, gpu: &eframe::Frame, print: Print, f: &mut Frame<'_>) {
        let Some(rs) = gpu.wgpu_render_state() else {
            f.error("Export for print needs the GPU renderer, which is not available");
            return;
        };
        if let Err(e) = print.check() {
            f.error(format!("Export for print: {e}"));
            return;
        }
        let design = f.editor.history.design();
        let window = print.window(design);
        match PngExport::start_window(&rs.device, &rs.queue, design, &window, f.prefs.antialias) {
            Ok(export) => {
                let export = export.with_pixels_per_metre(print.pixels_per_metre());
                let name = format!(
                    "marbling-{}ops-{:.0}x{:.0}mm-{}dpi.png",
                    design.ops.len(),
                    print.sheet.width_mm,
                    print.sheet.height_mm,
                    print.dpi
                );
                let (w, h) = export.size();
                f.info(format!("exporting {w}×{h} PNG for print ({print})…"));
                self.png = Some((export, name));
            }
            Err(e) => f.error(format!("Export for print: {e}")),
        }
    }

    /// Moves a running PNG export on by one tile and a running SVG export by its budget;
    /// hands a file over when complete.
    pub fn advance(&mut self, gpu: &eframe::Frame, ctx: &egui::Context, f: &mut Frame<'_>) {
        self.advance_png(gpu, ctx, f);
        self.svg.tick(ctx, f);
    }

    fn advance_png(&mut self, gpu: &eframe::Frame, ctx: &egui::Context, f: &mut Frame<'_>) {
        let Some((mut export, name)) = self.png.take() else {
            return;
        };
        let Some(rs) = gpu.wgpu_render_state() else {
            f.error("Export PNG: the GPU renderer went away");
            return;
        };
        match export.step(&rs.device, &rs.queue) {
            Ok(ExportStep::Working { .. }) => {
                self.png = Some((export, name));
                ctx.request_repaint();
            }
            Ok(ExportStep::Finished(image)) => match export.encode(&image) {
                Ok(bytes) => match platform::save_file(&name, "image/png", &bytes) {
                    Ok(()) => f.info(format!("exported {name}")),
                    Err(e) => f.error(e),
                },
                Err(e) => f.error(format!("Export PNG: {e}")),
            },
            Err(e) => f.error(format!("Export PNG: {e}")),
        }
    }

    /// Drops a PNG export under way (the GPU device that drew it was lost).
    pub fn drop_png(&mut self) {
        self.png = None;
    }

    /// The `data-exporting` hook's value for a PNG export under way: `<w>x<h>`.
    pub fn png_hook(&self) -> Option<String> {
        let (w, h) = self.png.as_ref()?.0.size();
        Some(format!("{w}x{h}"))
    }

    /// The `data-exporting` hook's value for an SVG export under way: `svg <n>%`.
    pub fn svg_hook(&self) -> Option<String> {
        Some(format!("svg {:.0}%", 100.0 * self.svg.progress()?))
    }
}
