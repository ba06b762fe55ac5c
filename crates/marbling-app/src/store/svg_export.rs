//! Export SVG: the design's ink outlines traced (marbling-vector's [`Tracer`], T = 1
//! design pixel) a frame's budget at a time, so the page keeps drawing while a long
//! design traces; Cancel drops the trace. The file is offered when the trace completes.

use crate::frame::Frame;
use marbling_core::Design;
use marbling_vector::{TraceOptions, Tracer, to_svg};

/// CPU time the trace takes per frame, milliseconds: half of the idle frame interval
/// the canvas aims at (one step may run over: a step is a share of one op's regions, a
/// few label rows, or a few contour tiles or regions).
pub const FRAME_BUDGET_MS: f64 = 50.0;

/// A running SVG export.
pub struct SvgExport {
    tracer: Tracer,
    /// The largest share of the work seen done (the tracer's total grows as it learns
    /// how many label rows and regions there are; what is shown never goes back).
    done: f32,
    /// The download's file name.
    pub name: String,
}

impl SvgExport {
    /// Starts tracing a copy of `design` (later edits do not change the export).
    pub fn start(design: &Design) -> Result<Self, String> {
        let name =
            crate::store::export::export_file_name(design, (design.width, design.height), "svg");
        let tracer =
            Tracer::new(design.clone(), &TraceOptions::default()).map_err(|e| e.to_string())?;
        Ok(Self {
            tracer,
            done: 0.0,
            name,
        })
    }

    /// Traces until `now()` passes `budget_ms` from the start; true once complete.
    pub fn advance(&mut self, budget_ms: f64, now: impl Fn() -> f64) -> Result<bool, String> {
        let complete = self
            .tracer
            .advance(budget_ms, now)
            .map_err(|e| e.to_string())?;
        let (done, total) = self.tracer.progress();
        let share = if complete || total == 0 {
            f32::from(complete)
        } else {
            done as f32 / total as f32
        };
        self.done = self.done.max(share);
        Ok(complete)
    }

    /// The SVG document of the completed trace.
    pub fn finish(self) -> Result<String, String> {
        let traced = self.tracer.finish().map_err(|e| e.to_string())?;
        Ok(to_svg(&traced))
    }

    /// Share of the work done, [0, 1]; it never goes back.
    pub fn progress(&self) -> f32 {
        self.done
    }
}

/// Export SVG as the side panel's Export section offers it: the button, or the running
/// trace's progress and Cancel.
#[derive(Default)]
pub(crate) struct SvgExporter {
    running: Option<SvgExport>,
}

impl SvgExporter {
    /// Share of the running trace done, [0, 1]; `None` when none runs.
    pub fn progress(&self) -> Option<f32> {
        self.running.as_ref().map(SvgExport::progress)
    }

    /// *Export SVG*, or the running trace's progress and *Cancel*.
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        if let Some(export) = &self.running {
            ui.label(format!(
                "tracing the SVG… {:.0} %",
                100.0 * export.progress()
            ));
            let cancel = ui.button("Cancel");
            frame.control("export-cancel", &cancel);
            if cancel.clicked() {
                self.running = None;
                frame.info("export cancelled");
            }
            return;
        }
        let svg = ui
            .button("Export SVG")
            .on_hover_text("Ink outlines traced forward, within 1 px");
        frame.control("export-svg", &svg);
        if svg.clicked() {
            match SvgExport::start(frame.editor.history.design()) {
                Ok(export) => {
                    frame.info("tracing the SVG…");
                    self.running = Some(export);
                }
                Err(e) => frame.error(format!("Export SVG: {e}")),
            }
        }
    }

    /// Moves a running trace on by one frame's budget; offers the file when done.
    pub fn tick(&mut self, ctx: &egui::Context, frame: &mut Frame<'_>) {
        let Some(mut export) = self.running.take() else {
            return;
        };
        let saved = match export.advance(FRAME_BUDGET_MS, crate::platform::now_ms) {
            Ok(false) => {
                self.running = Some(export);
                ctx.request_repaint();
                return;
            }
            Ok(true) => {
                let name = export.name.clone();
                export.finish().and_then(|svg| {
                    crate::platform::save_file(&name, "image/svg+xml", svg.as_bytes())
                        .map(|()| (name, svg.len()))
                })
            }
            Err(e) => Err(e),
        };
        match saved {
            Ok((name, bytes)) => frame.info(format!("exported {name} ({bytes} bytes)")),
            Err(e) => frame.error(format!("Export SVG: {e}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn a_budgeted_export_spreads_over_frames_and_is_the_whole_svg() {
        let design = random_design(3, 160, 120, 60, Mix::Mixed);
        let mut export = SvgExport::start(&design).expect("starts");
        // A clock that jumps past the budget at every reading: one step a frame.
        let clock = std::cell::Cell::new(0.0);
        let now = || {
            clock.set(clock.get() + 100.0);
            clock.get()
        };
        let mut frames = 1;
        let mut last = 0.0;
        while !export.advance(FRAME_BUDGET_MS, now).expect("traces") {
            frames += 1;
            assert!(export.progress() >= last);
            last = export.progress();
        }
        assert!(frames > 4, "{frames} frames: the trace was not spread out");
        assert_eq!(export.progress(), 1.0);
        assert_eq!(export.name, "marbling-60ops-160x120.svg");
        let whole =
            marbling_vector::design_to_svg(&design, &TraceOptions::default()).expect("traceable");
        assert_eq!(export.finish().expect("complete"), whole);
    }
}
